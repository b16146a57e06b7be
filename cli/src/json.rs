//! Reading the JSON input: one streaming pass of serde into typed values (the schema is in
//! `schema`), whose errors name the field (`sweep.profile.circle.radius`), and the value
//! types that check as they read, so that a bad or oversized input is refused before it
//! costs memory: finite and positive numbers, counts in a range, points, and lists with an
//! upper bound on their length ([`Bounded`]). The input itself is read through a counter
//! that stops at [`MAX_INPUT_BYTES`].

use rmfsurf::glam::DVec3;
use serde::de::{self, DeserializeOwned, Deserializer, IgnoredAny, SeqAccess, Visitor};
use serde::Deserialize;
use std::fmt;
use std::io::{self, BufReader, Read};
use std::marker::PhantomData;

/// Largest input read: 64 MiB. The largest inputs the library accepts (a wire of
/// `rmfsurf::wire::MAX_FACES` edges, a spine of tens of thousands of points) take a few MiB.
pub const MAX_INPUT_BYTES: u64 = 64 << 20;

/// A problem with the input, at a field.
#[derive(Debug, Clone, PartialEq)]
pub struct InputError {
    pub path: String,
    pub message: String,
}

impl InputError {
    pub fn at(path: impl Into<String>, message: impl Into<String>) -> Self {
        Self {
            path: path.into(),
            message: message.into(),
        }
    }
}

impl fmt::Display for InputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.path, self.message)
    }
}

pub type InputResult<T> = Result<T, InputError>;

/// A reader that fails once more than `left` bytes would have been read.
struct Limited<R> {
    inner: R,
    left: u64,
    exceeded: bool,
}

impl<R: Read> Read for Limited<R> {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        // One byte more than allowed tells a longer input from one of exactly the limit.
        let room = usize::try_from(self.left.saturating_add(1)).unwrap_or(usize::MAX);
        let wanted = buf.len().min(room);
        let n = self.inner.read(&mut buf[..wanted])?;
        if n as u64 > self.left {
            self.exceeded = true;
            return Err(io::Error::other("input too large"));
        }
        self.left -= n as u64;
        Ok(n)
    }
}

/// Reads one JSON value of type `T` from `reader`, named `source` in messages (a file
/// name, or `(stdin)`): syntax errors give line and column, others the field.
pub fn read<T: DeserializeOwned>(reader: impl Read, source: &str) -> InputResult<T> {
    let mut limited = Limited {
        inner: reader,
        left: MAX_INPUT_BYTES,
        exceeded: false,
    };
    let result = {
        let mut de =
            serde_json::Deserializer::from_reader(BufReader::with_capacity(1 << 16, &mut limited));
        match serde_path_to_error::deserialize::<_, T>(&mut de) {
            Ok(value) => de.end().map(|()| value).map_err(|e| (String::new(), e)),
            Err(e) => Err((e.path().to_string(), e.into_inner())),
        }
    };
    result.map_err(|(path, e)| {
        if limited.exceeded {
            return InputError::at(
                source,
                format!(
                    "the input is larger than {MAX_INPUT_BYTES} bytes (64 MiB), the limit of \
                     the tool"
                ),
            );
        }
        match e.classify() {
            serde_json::error::Category::Io => InputError::at(source, format!("cannot read: {e}")),
            serde_json::error::Category::Data => data_error(&path, &e),
            _ => InputError::at(source, format!("malformed JSON: {e}")),
        }
    })
}

/// The error of a value at `path` (serde_path_to_error's form, `.` for the top level),
/// without the position serde_json appends, and serde's messages on fields rewritten to
/// name the field in the path.
fn data_error(path: &str, e: &serde_json::Error) -> InputError {
    let text = e.to_string();
    let message = text
        .strip_suffix(&format!(" at line {} column {}", e.line(), e.column()))
        .unwrap_or(&text);
    let path = if path == "." { "" } else { path };
    let join = |key: &str| {
        if path.is_empty() {
            key.to_string()
        } else if path.ends_with(&format!(".{key}")) || path == key {
            path.to_string()
        } else {
            format!("{path}.{key}")
        }
    };
    // serde's own wording: "unknown field `k`, expected one of `a`, `b`" (or "expected `a`",
    // "there are no fields"), "missing field `k`", "duplicate field `k`", "invalid type:
    // string \"x\", expected an object" (every struct of the schema expects "an object").
    let field = |prefix: &str| {
        let rest = message.strip_prefix(prefix)?;
        let end = rest.find('`')?;
        Some((&rest[..end], &rest[end + 1..]))
    };
    let (path, message) = if let Some((key, rest)) = field("unknown field `") {
        let expected = rest.trim_start_matches(", ").replace('`', "");
        (join(key), format!("unknown field; {expected}"))
    } else if let Some((key, _)) = field("missing field `") {
        (join(key), "is missing".to_string())
    } else if let Some((key, _)) = field("duplicate field `") {
        (join(key), "is given twice".to_string())
    } else if let Some((got, wanted)) = message
        .strip_prefix("invalid type: ")
        .and_then(|m| m.rsplit_once(", expected "))
    {
        let got = got.replace('`', "");
        (path.to_string(), format!("must be {wanted}, got {got}"))
    } else {
        (path.to_string(), message.to_string())
    };
    InputError::at(
        if path.is_empty() {
            "(top level)".to_string()
        } else {
            path
        },
        message,
    )
}

/// The kind of JSON value a visitor was given instead of the one it wanted.
fn wrong<E: de::Error>(wanted: &str, got: &str) -> E {
    E::custom(format!("must be {wanted}, got {got}"))
}

/// Visitor methods for the JSON kinds a visitor does not take: each is an error naming
/// the kind, in the words of the value wanted.
macro_rules! refuse_other_kinds {
    ($wanted:expr; $($method:ident),*) => {
        $(refuse_other_kinds!(@ $method, $wanted);)*
    };
    (@ bool, $wanted:expr) => {
        fn visit_bool<E: de::Error>(self, _: bool) -> Result<Self::Value, E> {
            Err(wrong($wanted, "a boolean"))
        }
    };
    (@ str, $wanted:expr) => {
        fn visit_str<E: de::Error>(self, _: &str) -> Result<Self::Value, E> {
            Err(wrong($wanted, "a string"))
        }
    };
    (@ unit, $wanted:expr) => {
        fn visit_unit<E: de::Error>(self) -> Result<Self::Value, E> {
            Err(wrong($wanted, "null"))
        }
    };
    (@ seq, $wanted:expr) => {
        fn visit_seq<A: SeqAccess<'de>>(self, _: A) -> Result<Self::Value, A::Error> {
            Err(wrong($wanted, "an array"))
        }
    };
    (@ map, $wanted:expr) => {
        fn visit_map<A: de::MapAccess<'de>>(self, _: A) -> Result<Self::Value, A::Error> {
            Err(wrong($wanted, "an object"))
        }
    };
    (@ number, $wanted:expr) => {
        fn visit_u64<E: de::Error>(self, _: u64) -> Result<Self::Value, E> {
            Err(wrong($wanted, "a number"))
        }
        fn visit_i64<E: de::Error>(self, _: i64) -> Result<Self::Value, E> {
            Err(wrong($wanted, "a number"))
        }
        fn visit_f64<E: de::Error>(self, _: f64) -> Result<Self::Value, E> {
            Err(wrong($wanted, "a number"))
        }
    };
}

/// A finite number.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Number(pub f64);

struct NumberVisitor;

impl<'de> Visitor<'de> for NumberVisitor {
    type Value = f64;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a finite number")
    }

    fn visit_f64<E: de::Error>(self, x: f64) -> Result<f64, E> {
        if x.is_finite() {
            Ok(x)
        } else {
            Err(wrong("a finite number", "a number out of range"))
        }
    }

    fn visit_i64<E: de::Error>(self, x: i64) -> Result<f64, E> {
        Ok(x as f64)
    }

    fn visit_u64<E: de::Error>(self, x: u64) -> Result<f64, E> {
        Ok(x as f64)
    }

    refuse_other_kinds!("a finite number"; bool, str, unit, seq, map);
}

impl<'de> Deserialize<'de> for Number {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(NumberVisitor).map(Number)
    }
}

/// A finite positive number.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Positive(pub f64);

impl<'de> Deserialize<'de> for Positive {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let x = d.deserialize_any(NumberVisitor)?;
        if x > 0.0 {
            Ok(Positive(x))
        } else {
            Err(de::Error::custom(format!("must be positive, got {x}")))
        }
    }
}

/// A whole number in `LO..=HI`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Count<const LO: usize, const HI: usize>(pub usize);

struct CountVisitor<const LO: usize, const HI: usize>;

impl<const LO: usize, const HI: usize> CountVisitor<LO, HI> {
    fn refuse<E: de::Error>(got: impl fmt::Display) -> E {
        E::custom(format!(
            "must be a whole number from {LO} to {HI}, got {got}"
        ))
    }
}

impl<'de, const LO: usize, const HI: usize> Visitor<'de> for CountVisitor<LO, HI> {
    type Value = usize;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        write!(f, "a whole number from {LO} to {HI}")
    }

    fn visit_u64<E: de::Error>(self, n: u64) -> Result<usize, E> {
        match usize::try_from(n) {
            Ok(n) if (LO..=HI).contains(&n) => Ok(n),
            _ => Err(Self::refuse(n)),
        }
    }

    fn visit_i64<E: de::Error>(self, n: i64) -> Result<usize, E> {
        Err(Self::refuse(n))
    }

    fn visit_f64<E: de::Error>(self, x: f64) -> Result<usize, E> {
        // `{x:?}` keeps the fraction of 3.0, which is refused too.
        Err(Self::refuse(format!("{x:?}")))
    }

    fn visit_bool<E: de::Error>(self, b: bool) -> Result<usize, E> {
        Err(Self::refuse(b))
    }

    fn visit_str<E: de::Error>(self, _: &str) -> Result<usize, E> {
        Err(Self::refuse("a string"))
    }

    fn visit_unit<E: de::Error>(self) -> Result<usize, E> {
        Err(Self::refuse("null"))
    }

    fn visit_seq<A: SeqAccess<'de>>(self, _: A) -> Result<usize, A::Error> {
        Err(Self::refuse("an array"))
    }

    fn visit_map<A: de::MapAccess<'de>>(self, _: A) -> Result<usize, A::Error> {
        Err(Self::refuse("an object"))
    }
}

impl<'de, const LO: usize, const HI: usize> Deserialize<'de> for Count<LO, HI> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(CountVisitor::<LO, HI>).map(Count)
    }
}

/// `true` or `false`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bool(pub bool);

struct BoolVisitor;

impl<'de> Visitor<'de> for BoolVisitor {
    type Value = bool;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("true or false")
    }

    fn visit_bool<E: de::Error>(self, b: bool) -> Result<bool, E> {
        Ok(b)
    }

    refuse_other_kinds!("true or false"; number, str, unit, seq, map);
}

impl<'de> Deserialize<'de> for Bool {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(BoolVisitor).map(Bool)
    }
}

/// One of a fixed set of names, as a string.
pub struct NameVisitor<'n, T> {
    /// What the name is of, for messages ("method").
    pub what: &'static str,
    pub names: &'n [(&'static str, T)],
}

impl<'de, T: Copy> Visitor<'de> for NameVisitor<'_, T> {
    type Value = T;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        write!(f, "a {} name", self.what)
    }

    fn visit_str<E: de::Error>(self, name: &str) -> Result<T, E> {
        match self.names.iter().find(|(n, _)| *n == name) {
            Some(&(_, value)) => Ok(value),
            None => {
                let names: Vec<&str> = self.names.iter().map(|(n, _)| *n).collect();
                Err(E::custom(format!(
                    "unknown {} \"{name}\"; expected one of {}",
                    self.what,
                    names.join(", ")
                )))
            }
        }
    }

    refuse_other_kinds!("a string"; bool, number, unit, seq, map);
}

/// Reads the coordinates of a point: two or three numbers (`planar`), or exactly three.
struct PointVisitor {
    planar: bool,
}

impl PointVisitor {
    fn shape(&self) -> &'static str {
        if self.planar {
            "[x, y] or [x, y, z]"
        } else {
            "[x, y, z]"
        }
    }
}

impl<'de> Visitor<'de> for PointVisitor {
    type Value = DVec3;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str(self.shape())
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<DVec3, A::Error> {
        let mut xs = [0.0; 3];
        let mut n = 0usize;
        // The numbers past the third are checked and counted, not kept.
        while let Some(Number(x)) = seq.next_element::<Number>()? {
            if let Some(slot) = xs.get_mut(n) {
                *slot = x;
            }
            n += 1;
        }
        match (n, self.planar) {
            (3, _) | (2, true) => Ok(DVec3::from_array(xs)),
            _ => Err(de::Error::custom(format!(
                "must be {}, got {n} numbers",
                self.shape()
            ))),
        }
    }

    refuse_other_kinds!("an array"; bool, number, str, unit, map);
}

/// A point or vector in space: `[x, y, z]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Vec3(pub DVec3);

impl<'de> Deserialize<'de> for Vec3 {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(PointVisitor { planar: false }).map(Vec3)
    }
}

/// A point of a profile: `[x, y]`, or `[x, y, z]` with z ignored by the sweep.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Point2(pub DVec3);

impl<'de> Deserialize<'de> for Point2 {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(PointVisitor { planar: true }).map(Point2)
    }
}

/// The longest list a field may have, and why.
pub trait Bound {
    const MAX: usize;
    /// What the items are, plural ("edges").
    const ITEMS: &'static str;
    /// The bound's reason, after a colon.
    const WHY: &'static str;
}

/// A list of at most `L::MAX` items, refused at item `L::MAX + 1`: reading never holds
/// more than the bound.
pub struct Bounded<T, L>(pub Vec<T>, PhantomData<L>);

impl<T: fmt::Debug, L> fmt::Debug for Bounded<T, L> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_list().entries(&self.0).finish()
    }
}

impl<T, L> Bounded<T, L> {
    pub fn into_vec(self) -> Vec<T> {
        self.0
    }
}

struct BoundedVisitor<T, L>(PhantomData<(T, L)>);

impl<'de, T: Deserialize<'de>, L: Bound> Visitor<'de> for BoundedVisitor<T, L> {
    type Value = Vec<T>;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        write!(f, "an array of at most {} {}", L::MAX, L::ITEMS)
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Vec<T>, A::Error> {
        let mut items = Vec::new();
        while items.len() < L::MAX {
            match seq.next_element()? {
                Some(item) => items.push(item),
                None => return Ok(items),
            }
        }
        match seq.next_element::<IgnoredAny>()? {
            None => Ok(items),
            Some(_) => Err(de::Error::custom(format!(
                "has more than {} {}: {}",
                L::MAX,
                L::ITEMS,
                L::WHY
            ))),
        }
    }

    refuse_other_kinds!("an array"; bool, number, str, unit, map);
}

impl<'de, T: Deserialize<'de>, L: Bound> Deserialize<'de> for Bounded<T, L> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(BoundedVisitor::<T, L>(PhantomData))
            .map(|items| Bounded(items, PhantomData))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    struct Three;

    impl Bound for Three {
        const MAX: usize = 3;
        const ITEMS: &'static str = "things";
        const WHY: &'static str = "a test bound";
    }

    #[derive(Debug, Deserialize)]
    #[serde(deny_unknown_fields, expecting = "an object")]
    #[allow(dead_code)]
    struct Sample {
        radius: Positive,
        point: Option<Vec3>,
        corners: Option<Bounded<Point2, Three>>,
        degree: Option<Count<1, 64>>,
        solid: Option<Bool>,
    }

    #[derive(Debug, Deserialize)]
    #[serde(deny_unknown_fields, expecting = "an object")]
    #[allow(dead_code)]
    struct Top {
        sample: Sample,
    }

    fn error(json: &str) -> String {
        read::<Top>(json.as_bytes(), "in.json")
            .unwrap_err()
            .to_string()
    }

    #[test]
    fn errors_name_the_field() {
        let ok: Top = read(
            r#"{"sample": {"radius": 2, "corners": [[1, 2], [3, 4, 5]]}}"#.as_bytes(),
            "in.json",
        )
        .unwrap();
        assert_eq!(ok.sample.radius, Positive(2.0));
        for (json, expected) in [
            (
                r#"{"sample": {"radius": -1}}"#,
                "sample.radius: must be positive, got -1",
            ),
            (
                r#"{"sample": {"radius": 1, "point": [1, "x", 3]}}"#,
                "sample.point[1]: must be a finite number, got a string",
            ),
            (
                r#"{"sample": {"radius": 1, "point": [1, 2]}}"#,
                "sample.point: must be [x, y, z], got 2 numbers",
            ),
            (
                r#"{"sample": {"radius": 1, "corners": [[1, 2, 3, 4]]}}"#,
                "sample.corners[0]: must be [x, y] or [x, y, z], got 4 numbers",
            ),
            (
                r#"{"sample": {"radius": 1, "corners": [[0, 0], [0, 0], [0, 0], [0, 0]]}}"#,
                "sample.corners: has more than 3 things: a test bound",
            ),
            (
                r#"{"sample": {"radius": 1, "corners": {}}}"#,
                "sample.corners: must be an array, got an object",
            ),
            (
                r#"{"sample": {"radius": 1, "degree": 2.5}}"#,
                "sample.degree: must be a whole number from 1 to 64, got 2.5",
            ),
            (
                r#"{"sample": {"radius": 1, "solid": 1}}"#,
                "sample.solid: must be true or false, got a number",
            ),
            (
                r#"{"sample": {"radius": 1, "raduis": 1}}"#,
                "sample.raduis: unknown field; expected one of radius, point, corners, degree, solid",
            ),
            (r#"{"sample": {}}"#, "sample.radius: is missing"),
            (
                r#"{"sample": {"radius": 1, "radius": 1}}"#,
                "sample.radius: is given twice",
            ),
            (r#"{}"#, "sample: is missing"),
            (r#"{"sample": "x"}"#, "sample: must be an object, got string \"x\""),
            (r#"7"#, "(top level): must be an object, got integer 7"),
        ] {
            let e = error(json);
            assert!(e.starts_with(expected) || e == expected, "{json}: {e}");
        }
        assert!(error("{\"sample\": ").starts_with("in.json: malformed JSON: EOF"));
        assert!(error(r#"{"sample": {"radius": 1}} x"#)
            .starts_with("in.json: malformed JSON: trailing characters"));
    }

    #[test]
    fn the_input_is_read_up_to_the_limit() {
        let mut reader = Limited {
            inner: io::repeat(b' '),
            left: 10,
            exceeded: false,
        };
        let mut buf = [0u8; 4];
        assert_eq!(reader.read(&mut buf).unwrap(), 4);
        assert_eq!(reader.read(&mut buf).unwrap(), 4);
        assert!(!reader.exceeded);
        assert!(reader.read(&mut buf).is_err() && reader.exceeded);
        let e = read::<Top>(io::repeat(b' '), "(stdin)").unwrap_err();
        assert_eq!(e.path, "(stdin)");
        assert!(e.message.contains("larger than 67108864 bytes"), "{e}");
    }
}
