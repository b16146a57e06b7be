//! Turns the fuzzer's bytes into the numbers a geometry API meets in the wild.
//!
//! Raw bytes reinterpreted as doubles are almost always huge, tiny or NaN; the inputs that
//! break geometry code are structured: special values (NaN, ±Inf, −0, subnormals, 1e±300),
//! *near-duplicates* of values already used, points on a line through earlier points,
//! tangents that are parallel, antiparallel or nearly parallel to earlier ones. Each draw
//! reads a tag byte that picks one of these shapes, then the bytes it needs. When the bytes
//! run out every draw returns a fixed ordinary value, so any prefix of an input is valid.

use rmfsurf_capi::RmfVec3;
use std::f64::consts::FRAC_1_SQRT_2;

/// Doubles that break naive geometry code.
const SPECIAL: [f64; 16] = [
    f64::NAN,
    f64::INFINITY,
    f64::NEG_INFINITY,
    -0.0,
    5e-324, // smallest subnormal
    2.2250738585072014e-308,
    1e-300,
    -1e-300,
    1e300,
    -1e300,
    f64::MAX,
    f64::MIN,
    1e-12,
    1e12,
    f64::EPSILON,
    1.0 + f64::EPSILON,
];

/// Ordinary values, from which valid data are built.
const ORDINARY: [f64; 16] = [
    0.0,
    1.0,
    -1.0,
    0.5,
    -0.5,
    2.0,
    -2.0,
    0.25,
    3.0,
    0.1,
    -0.1,
    10.0,
    FRAC_1_SQRT_2,
    1.5,
    -3.0,
    0.3,
];

/// Remembered draws, for near-duplicates and collinear or parallel relations.
const MEMORY: usize = 8;

/// A reader of fuzzer bytes.
pub struct Input<'a> {
    bytes: &'a [u8],
    scalars: Vec<f64>,
    vectors: Vec<RmfVec3>,
}

impl<'a> Input<'a> {
    pub fn new(bytes: &'a [u8]) -> Self {
        Self {
            bytes,
            scalars: Vec::new(),
            vectors: Vec::new(),
        }
    }

    /// True when every byte has been read.
    pub fn is_empty(&self) -> bool {
        self.bytes.is_empty()
    }

    /// The next byte (0 when exhausted).
    pub fn byte(&mut self) -> u8 {
        match self.bytes.split_first() {
            Some((&b, rest)) => {
                self.bytes = rest;
                b
            }
            None => 0,
        }
    }

    fn u64(&mut self) -> u64 {
        (0..8).fold(0u64, |acc, _| (acc << 8) | u64::from(self.byte()))
    }

    /// A number below `n` (n ≥ 1).
    pub fn below(&mut self, n: usize) -> usize {
        usize::from(self.byte()) % n
    }

    /// A flag.
    pub fn flag(&mut self) -> bool {
        self.byte() & 1 == 1
    }

    /// A 32-bit code: mostly small (enumerations, degrees), sometimes any value.
    pub fn code(&mut self) -> u32 {
        match self.byte() {
            250..=255 => self.u64() as u32,
            b => u32::from(b % 12),
        }
    }

    /// An amount of work asked of the library (a count of samples, segments, pieces):
    /// mostly small, sometimes absurdly large — which must be refused, never attempted.
    pub fn work(&mut self) -> usize {
        match self.byte() {
            252 => usize::MAX,
            253 => 1 << 40,
            254 => isize::MAX as usize + 1,
            255 => (1 << 31) + self.below(7),
            b => usize::from(b % 48),
        }
    }

    /// The length of an input array (small: the library's cost grows with it).
    pub fn len(&mut self, max: usize) -> usize {
        self.below(max + 1)
    }

    /// A double of any of the shapes in the module comment.
    pub fn f64(&mut self) -> f64 {
        let value = match self.byte() % 8 {
            0 | 1 => ORDINARY[self.below(ORDINARY.len())],
            2 => SPECIAL[self.below(SPECIAL.len())],
            3 => f64::from_bits(self.u64()),
            4 => {
                // A small decimal: integers and tenths in [-12.8, 12.7].
                f64::from(self.byte() as i8) / 10.0
            }
            5 => {
                // A near-duplicate: an earlier value moved by a few ulps or by a relative 1e-k.
                let base = self.recall_scalar();
                match self.byte() % 3 {
                    0 => f64::from_bits(base.to_bits().wrapping_add(u64::from(self.byte() % 4))),
                    1 => base * (1.0 + 10f64.powi(-i32::from(self.byte() % 16))),
                    _ => base + 10f64.powi(-i32::from(self.byte() % 16)),
                }
            }
            6 => self.recall_scalar(),
            _ => {
                // Any magnitude: mantissa from a byte, exponent from 1e-308 to 1e308.
                let mantissa = f64::from(self.byte() as i8) / 16.0;
                mantissa * 10f64.powi(i32::from(self.byte()) * 616 / 255 - 308)
            }
        };
        if self.scalars.len() == MEMORY {
            self.scalars.remove(0);
        }
        self.scalars.push(value);
        value
    }

    fn recall_scalar(&mut self) -> f64 {
        if self.scalars.is_empty() {
            return 1.0;
        }
        let i = self.below(self.scalars.len());
        self.scalars[i]
    }

    fn recall_vector(&mut self) -> RmfVec3 {
        if self.vectors.is_empty() {
            return RmfVec3 {
                x: 1.0,
                y: 0.0,
                z: 0.0,
            };
        }
        let i = self.below(self.vectors.len());
        self.vectors[i]
    }

    /// A point or direction: free, or related to earlier ones — equal, nearly equal,
    /// (anti)parallel, nearly parallel, on the line through two of them.
    pub fn vec3(&mut self) -> RmfVec3 {
        let value = match self.byte() % 8 {
            0..=2 => RmfVec3 {
                x: self.f64(),
                y: self.f64(),
                z: self.f64(),
            },
            3 => self.recall_vector(),
            4 => {
                // Parallel or antiparallel: a scaled copy (the scale may be negative or 0).
                let (a, s) = (self.recall_vector(), self.f64());
                scale(a, s)
            }
            5 => {
                // Nearly equal or nearly parallel: a copy moved by 10^-k of a free vector.
                let a = self.recall_vector();
                let (d, k) = (self.small_vec3(), self.byte() % 17);
                add(a, scale(d, 10f64.powi(-i32::from(k))))
            }
            6 => {
                // Collinear: a + s (b − a).
                let (a, b, s) = (self.recall_vector(), self.recall_vector(), self.f64());
                add(a, scale(add(b, scale(a, -1.0)), s))
            }
            _ => self.small_vec3(),
        };
        if self.vectors.len() == MEMORY {
            self.vectors.remove(0);
        }
        self.vectors.push(value);
        value
    }

    /// A vector with ordinary components (valid data, most of the time).
    pub fn small_vec3(&mut self) -> RmfVec3 {
        let mut component = || f64::from(self.byte() as i8) / 32.0;
        RmfVec3 {
            x: component(),
            y: component(),
            z: component(),
        }
    }

    /// `n` doubles.
    pub fn f64s(&mut self, n: usize) -> Vec<f64> {
        (0..n).map(|_| self.f64()).collect()
    }

    /// `n` points or directions.
    pub fn vec3s(&mut self, n: usize) -> Vec<RmfVec3> {
        (0..n).map(|_| self.vec3()).collect()
    }

    /// A non-decreasing sequence of `n` values (knots, parameters), sometimes with
    /// repeated or arbitrary entries.
    pub fn increasing(&mut self, n: usize) -> Vec<f64> {
        if self.below(4) == 0 {
            return self.f64s(n);
        }
        let mut value = self.f64();
        (0..n)
            .map(|_| {
                let v = value;
                value += match self.byte() % 4 {
                    0 => 0.0,
                    1 => self.f64().abs(),
                    _ => 1.0,
                };
                v
            })
            .collect()
    }
}

fn add(a: RmfVec3, b: RmfVec3) -> RmfVec3 {
    RmfVec3 {
        x: a.x + b.x,
        y: a.y + b.y,
        z: a.z + b.z,
    }
}

fn scale(a: RmfVec3, s: f64) -> RmfVec3 {
    RmfVec3 {
        x: a.x * s,
        y: a.y * s,
        z: a.z * s,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exhausted_input_gives_ordinary_values() {
        let mut input = Input::new(&[]);
        assert!(input.is_empty());
        assert_eq!(input.f64(), 0.0);
        assert_eq!(input.work(), 0);
    }
}
