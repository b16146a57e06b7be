//! Reading the JSON input with errors that name the field: every value is reached through
//! a [`Field`] that knows its path (`sweep.profile.circle.radius`), so a bad value is
//! reported where it is, never as a bare type error.

use rmfsurf::glam::DVec3;
use serde_json::{Map, Value};
use std::fmt;

/// A problem with the input, at a field.
#[derive(Debug, Clone, PartialEq)]
pub struct InputError {
    pub path: String,
    pub message: String,
}

impl fmt::Display for InputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.path, self.message)
    }
}

pub type InputResult<T> = Result<T, InputError>;

/// A JSON value and where it is in the document.
#[derive(Clone, Debug)]
pub struct Field<'a> {
    path: String,
    value: &'a Value,
}

/// The parsed input.
pub struct Document {
    root: Value,
}

impl Document {
    /// Parses JSON text; syntax errors give line and column.
    pub fn parse(text: &str, source: &str) -> InputResult<Self> {
        serde_json::from_str(text)
            .map(|root| Self { root })
            .map_err(|e| InputError {
                path: source.to_string(),
                message: format!("malformed JSON: {e}"),
            })
    }

    pub fn root(&self) -> Field<'_> {
        Field {
            path: String::new(),
            value: &self.root,
        }
    }
}

impl<'a> Field<'a> {
    pub fn path(&self) -> &str {
        if self.path.is_empty() {
            "(top level)"
        } else {
            &self.path
        }
    }

    /// An error at this field.
    pub fn error<T>(&self, message: impl Into<String>) -> InputResult<T> {
        Err(InputError {
            path: self.path().to_string(),
            message: message.into(),
        })
    }

    fn child(&self, key: &str) -> String {
        if self.path.is_empty() {
            key.to_string()
        } else {
            format!("{}.{key}", self.path)
        }
    }

    fn object(&self) -> InputResult<&'a Map<String, Value>> {
        match self.value {
            Value::Object(map) => Ok(map),
            other => self.error(format!("must be an object, got {}", kind(other))),
        }
    }

    /// The field `key` if present (and not null).
    pub fn optional(&self, key: &str) -> InputResult<Option<Field<'a>>> {
        Ok(self
            .object()?
            .get(key)
            .filter(|v| !v.is_null())
            .map(|value| Field {
                path: self.child(key),
                value,
            }))
    }

    /// The field `key`, which must be present.
    pub fn required(&self, key: &str) -> InputResult<Field<'a>> {
        self.optional(key)?.map_or_else(
            || {
                Err(InputError {
                    path: self.child(key),
                    message: "is missing".into(),
                })
            },
            Ok,
        )
    }

    /// Fails on a key not in `allowed` (catches misspelt options instead of ignoring them).
    pub fn only(&self, allowed: &[&str]) -> InputResult<()> {
        for key in self.object()?.keys() {
            if !allowed.contains(&key.as_str()) {
                return Err(InputError {
                    path: self.child(key),
                    message: format!("unknown field; expected one of {}", allowed.join(", ")),
                });
            }
        }
        Ok(())
    }

    /// The one key of an object that must have exactly one of `choices` (a tagged union
    /// such as `{"circle": {...}}`), and its value.
    pub fn variant(&self, choices: &[&str]) -> InputResult<(&'a str, Field<'a>)> {
        self.variant_of(choices, &[])
    }

    /// As [`variant`](Self::variant), with the fields `others` allowed beside the choice.
    pub fn variant_of(
        &self,
        choices: &[&str],
        others: &[&str],
    ) -> InputResult<(&'a str, Field<'a>)> {
        let map = self.object()?;
        self.only(&[choices, others].concat())?;
        let present: Vec<&'a String> = map
            .keys()
            .filter(|k| choices.contains(&k.as_str()))
            .collect();
        match present.as_slice() {
            [key] => Ok((key.as_str(), self.required(key)?)),
            [] => self.error(format!("needs one of {}", choices.join(", "))),
            _ => self.error(format!("give only one of {}", choices.join(", "))),
        }
    }

    pub fn string(&self) -> InputResult<&'a str> {
        match self.value {
            Value::String(s) => Ok(s),
            other => self.error(format!("must be a string, got {}", kind(other))),
        }
    }

    pub fn boolean(&self) -> InputResult<bool> {
        match self.value {
            Value::Bool(b) => Ok(*b),
            other => self.error(format!("must be true or false, got {}", kind(other))),
        }
    }

    pub fn number(&self) -> InputResult<f64> {
        match self.value.as_f64() {
            Some(x) if x.is_finite() => Ok(x),
            _ => self.error(format!("must be a finite number, got {}", kind(self.value))),
        }
    }

    pub fn positive(&self) -> InputResult<f64> {
        let x = self.number()?;
        if x > 0.0 {
            Ok(x)
        } else {
            self.error(format!("must be positive, got {x}"))
        }
    }

    /// A whole number in `lo..=hi`.
    pub fn count(&self, lo: usize, hi: usize) -> InputResult<usize> {
        match self.value.as_u64() {
            Some(n) if (lo as u64..=hi as u64).contains(&n) => Ok(n as usize),
            _ => self.error(format!(
                "must be a whole number from {lo} to {hi}, got {}",
                self.value
            )),
        }
    }

    pub fn array(&self) -> InputResult<Vec<Field<'a>>> {
        match self.value {
            Value::Array(items) => Ok(items
                .iter()
                .enumerate()
                .map(|(i, value)| Field {
                    path: format!("{}[{i}]", self.path()),
                    value,
                })
                .collect()),
            other => self.error(format!("must be an array, got {}", kind(other))),
        }
    }

    pub fn numbers(&self) -> InputResult<Vec<f64>> {
        self.array()?.iter().map(Field::number).collect()
    }

    /// `[x, y, z]`, or `[x, y]` with z = 0 when `planar_allowed`.
    fn coordinates(&self, planar_allowed: bool) -> InputResult<DVec3> {
        let xs = self.numbers()?;
        match (xs.as_slice(), planar_allowed) {
            ([x, y, z], _) => Ok(DVec3::new(*x, *y, *z)),
            ([x, y], true) => Ok(DVec3::new(*x, *y, 0.0)),
            (_, true) => self.error(format!(
                "must be [x, y] or [x, y, z], got {} numbers",
                xs.len()
            )),
            (_, false) => self.error(format!("must be [x, y, z], got {} numbers", xs.len())),
        }
    }

    pub fn vec3(&self) -> InputResult<DVec3> {
        self.coordinates(false)
    }

    /// A point of a profile: `[x, y]` (or `[x, y, z]`, z ignored by the sweep).
    pub fn point_2d(&self) -> InputResult<DVec3> {
        self.coordinates(true)
    }
}

fn kind(v: &Value) -> &'static str {
    match v {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn doc(text: &str) -> Document {
        Document::parse(text, "input.json").unwrap()
    }

    #[test]
    fn errors_name_the_field() {
        let d = doc(r#"{"sweep": {"profile": {"circle": {"radius": -1}}, "spine": [1, "x"]}}"#);
        let sweep = d.root().required("sweep").unwrap();
        let radius = sweep
            .required("profile")
            .and_then(|p| p.variant(&["circle", "line"]))
            .and_then(|(_, c)| c.required("radius"))
            .unwrap();
        assert_eq!(
            radius.positive().unwrap_err().to_string(),
            "sweep.profile.circle.radius: must be positive, got -1"
        );
        let spine = sweep.required("spine").unwrap();
        assert_eq!(
            spine.numbers().unwrap_err().to_string(),
            "sweep.spine[1]: must be a finite number, got a string"
        );
        assert_eq!(
            sweep.required("method").unwrap_err().to_string(),
            "sweep.method: is missing"
        );
        assert!(sweep
            .only(&["profile"])
            .unwrap_err()
            .to_string()
            .starts_with("sweep.spine: unknown field"));
        let e = Document::parse("{\"a\": ", "in.json").err().unwrap();
        assert!(
            e.to_string().starts_with("in.json: malformed JSON: EOF"),
            "{e}"
        );
    }
}
