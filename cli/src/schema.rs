//! The input as serde reads it: one struct per JSON object, every field typed, unknown
//! fields refused. A tagged union such as `{"circle": {...}}` is a struct of optional
//! fields here, and `job` checks that exactly one is given (naming the choices), as it
//! checks what depends on several fields. Lists have the bounds below, derived from the
//! library's, so that reading stops at the first item too many.

use crate::json::{Bool, Bound, Bounded, Count, NameVisitor, Number, Point2, Positive, Vec3};
use rmfsurf::glam::DVec3;
use rmfsurf::{
    sheet::Reference, wire::Corner, wire::PipeFrame, wire::SweepFrame, wire::MAX_FACES,
    SpineMethod, MAX_DEGREE, MAX_SWEEP_POLES,
};
use serde::de::{self, Deserializer, MapAccess, SeqAccess, Visitor};
use serde::Deserialize;
use std::fmt;

/// Largest tessellation steps per patch accepted from the input.
pub const MAX_STEPS: usize = 1000;
/// Largest `max_pieces` of a cone spline or sheet, and most elements of a cone spline.
pub const MAX_PIECES: usize = 1_000_000;

/// Edges of a wire.
pub struct Edges;

impl Bound for Edges {
    const MAX: usize = MAX_FACES;
    const ITEMS: &'static str = "edges";
    const WHY: &'static str =
        "a wire sweep has at most rmfsurf::wire::MAX_FACES lateral faces, one or more per edge";
}

/// Holes of a wire sweep's profile.
pub struct Holes;

impl Bound for Holes {
    const MAX: usize = MAX_FACES;
    const ITEMS: &'static str = "holes";
    const WHY: &'static str =
        "a wire sweep has at most rmfsurf::wire::MAX_FACES lateral faces, one or more per hole";
}

/// Poles of a NURBS curve, or of one row of a surface.
pub struct Poles;

impl Bound for Poles {
    const MAX: usize = MAX_SWEEP_POLES;
    const ITEMS: &'static str = "poles";
    const WHY: &'static str = "no sweep has more control points (rmfsurf::MAX_SWEEP_POLES)";
}

/// Weights of a NURBS curve, or of one row of a surface.
pub struct Weights;

impl Bound for Weights {
    const MAX: usize = MAX_SWEEP_POLES;
    const ITEMS: &'static str = "weights";
    const WHY: &'static str = "one per pole, and no sweep has more control points \
                               (rmfsurf::MAX_SWEEP_POLES)";
}

/// Knots of a NURBS curve or surface: poles + degree + 1.
pub struct Knots;

impl Bound for Knots {
    const MAX: usize = MAX_SWEEP_POLES + MAX_DEGREE + 1;
    const ITEMS: &'static str = "knots";
    const WHY: &'static str = "poles + degree + 1, with at most rmfsurf::MAX_SWEEP_POLES \
                               poles and degree rmfsurf::MAX_DEGREE";
}

/// Rows of poles (or weights) of a ruled surface.
pub struct Rows;

impl Bound for Rows {
    const MAX: usize = 2;
    const ITEMS: &'static str = "rows";
    const WHY: &'static str =
        "a developable ruled surface has degree_u = 1 and two rows of poles, its rails";
}

/// Knots of a wire sweep's scale law.
pub struct ScaleKnots;

impl Bound for ScaleKnots {
    const MAX: usize = MAX_FACES;
    const ITEMS: &'static str = "knots";
    const WHY: &'static str = "each knot cuts the wire, and a wire sweep has at most \
                               rmfsurf::wire::MAX_FACES lateral faces";
}

/// Intermediate sections of a wire sweep through sections.
pub struct Sections;

impl Bound for Sections {
    const MAX: usize = MAX_FACES;
    const ITEMS: &'static str = "sections";
    const WHY: &'static str = "each section cuts the wire, and a wire sweep has at most \
                               rmfsurf::wire::MAX_FACES lateral faces";
}

/// Hermite points and tangents of a spine.
pub struct Points;

impl Bound for Points {
    const MAX: usize = MAX_SWEEP_POLES;
    const ITEMS: &'static str = "points";
    const WHY: &'static str = "each adds spine control points, and no sweep has more than \
                               rmfsurf::MAX_SWEEP_POLES";
}

/// Corners of a polygon.
pub struct Corners;

impl Bound for Corners {
    const MAX: usize = MAX_SWEEP_POLES;
    const ITEMS: &'static str = "corners";
    const WHY: &'static str = "each is a control point, and no sweep has more than \
                               rmfsurf::MAX_SWEEP_POLES";
}

/// Elements a cone spline interpolates.
pub struct Elements;

impl Bound for Elements {
    const MAX: usize = MAX_PIECES;
    const ITEMS: &'static str = "elements";
    const WHY: &'static str = "a cone spline has at most 1000000 pieces (max_pieces)";
}

/// The whole input: one of `sweep`, `cone_spline`, `sheet`, and `mesh`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, expecting = "an object")]
pub struct Input {
    pub sweep: Option<Sweep>,
    pub cone_spline: Option<Cone>,
    pub sheet: Option<Sheet>,
    pub mesh: Option<Mesh>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, expecting = "an object")]
pub struct Mesh {
    pub u_steps: Option<Count<1, MAX_STEPS>>,
    pub v_steps: Option<Count<1, MAX_STEPS>>,
    pub thickness: Option<Positive>,
}

/// A sweep along a curve or along a wire: the fields of both; `job` refuses those of the
/// other kind.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, expecting = "an object")]
pub struct Sweep {
    pub spine: Spine,
    pub method: Option<MethodName>,
    pub tolerance: Option<Positive>,
    pub initial_normal: Option<Vec3>,
    pub profile: Profile,
    pub corner: Option<CornerName>,
    pub join_tolerance: Option<Positive>,
    pub twist: Option<Number>,
    pub closure_symmetry: Option<Count<0, { 1 << 16 }>>,
    pub solid: Option<Bool>,
    pub frame: Option<FrameName>,
    /// How a round profile is swept along curve edges (`"rmf"`, the default, or
    /// `"lightest"`).
    pub pipe_frame: Option<PipeFrameName>,
    pub scale: Option<Scale>,
    /// Knots of the scale law: `[[fraction, scale], ...]`, σ piecewise linear through them.
    pub scale_knots: Option<Bounded<ScaleKnot, ScaleKnots>>,
    /// The section at the wire's end (same form as `profile`): a sweep between two profiles.
    pub end_profile: Option<Profile>,
    /// The sections between the start (`profile`) and the end (`end_profile`): a sweep
    /// through sections.
    pub sections: Option<Bounded<SectionIn, Sections>>,
}

/// `{"at": fraction, "profile": {...}, "holes": [...]}`: a section a sweep passes through,
/// at a fraction of the wire's length in (0, 1) (increasing from section to section:
/// checked by the library).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, expecting = "an object")]
pub struct SectionIn {
    pub at: Fraction,
    pub profile: Profile,
    pub holes: Option<Bounded<Hole, Holes>>,
}

impl Sweep {
    /// The fields given that only a sweep along a wire has.
    pub fn wire_fields(&self) -> Vec<&'static str> {
        [
            ("corner", self.corner.is_some()),
            ("join_tolerance", self.join_tolerance.is_some()),
            ("twist", self.twist.is_some()),
            ("closure_symmetry", self.closure_symmetry.is_some()),
            ("solid", self.solid.is_some()),
            ("frame", self.frame.is_some()),
            ("pipe_frame", self.pipe_frame.is_some()),
            ("scale", self.scale.is_some()),
            ("scale_knots", self.scale_knots.is_some()),
            ("end_profile", self.end_profile.is_some()),
            ("sections", self.sections.is_some()),
        ]
        .into_iter()
        .filter_map(|(name, given)| given.then_some(name))
        .collect()
    }
}

/// `{"nurbs"}`, `{"points", "tangents"}` or `{"wire"}`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, expecting = "an object")]
pub struct Spine {
    pub nurbs: Option<Nurbs<Vec3>>,
    pub points: Option<Bounded<Vec3, Points>>,
    pub tangents: Option<Bounded<Vec3, Points>>,
    pub wire: Option<Bounded<Edge, Edges>>,
}

/// One of `line`, `arc`, `nurbs`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, expecting = "an object")]
pub struct Edge {
    pub line: Option<LineEdge>,
    pub arc: Option<ArcEdge>,
    pub nurbs: Option<Nurbs<Vec3>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, expecting = "an object")]
pub struct LineEdge {
    pub from: Vec3,
    pub to: Vec3,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, expecting = "an object")]
pub struct ArcEdge {
    pub start: Vec3,
    pub through: Vec3,
    pub end: Vec3,
}

/// One of `circle`, `line`, `polygon`, `nurbs`; `holes` for wire sweeps.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, expecting = "an object")]
pub struct Profile {
    pub circle: Option<Circle>,
    pub line: Option<Line>,
    pub polygon: Option<Bounded<Point2, Corners>>,
    pub nurbs: Option<Nurbs<Point2>>,
    pub holes: Option<Bounded<Hole, Holes>>,
}

/// One of `circle`, `polygon`, `nurbs`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, expecting = "an object")]
pub struct Hole {
    pub circle: Option<Circle>,
    pub polygon: Option<Bounded<Point2, Corners>>,
    pub nurbs: Option<Nurbs<Point2>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, expecting = "an object")]
pub struct Circle {
    pub radius: Positive,
    pub center: Option<Point2>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, expecting = "an object")]
pub struct Line {
    pub from: Point2,
    pub to: Point2,
}

/// A NURBS curve's data, its poles of type `P` (`Vec3`, or `Point2` in a profile).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, expecting = "an object")]
pub struct Nurbs<P> {
    pub degree: Count<1, MAX_DEGREE>,
    pub poles: Bounded<P, Poles>,
    pub weights: Option<Bounded<Number, Weights>>,
    pub knots: Bounded<Number, Knots>,
}

/// A NURBS surface's data: poles and weights in rows, one per u index.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, expecting = "an object")]
pub struct Surface {
    pub degree_u: Count<1, MAX_DEGREE>,
    pub degree_v: Count<1, MAX_DEGREE>,
    pub poles: Bounded<Bounded<Vec3, Poles>, Rows>,
    pub weights: Option<Bounded<Bounded<Number, Weights>, Rows>>,
    pub knots_u: Bounded<Number, Knots>,
    pub knots_v: Bounded<Number, Knots>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, expecting = "an object")]
pub struct Cone {
    pub developable: Developable,
    pub tolerance: Option<Positive>,
    pub max_pieces: Option<Count<2, MAX_PIECES>>,
    pub strip: Strip,
}

/// One of `tangent_surface`, `ruled`, `elements`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, expecting = "an object")]
pub struct Developable {
    pub tangent_surface: Option<TangentSurface>,
    pub ruled: Option<Ruled>,
    pub elements: Option<Bounded<Element, Elements>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, expecting = "an object")]
pub struct TangentSurface {
    pub curve: CurveNurbs,
    pub v_min: Number,
    pub v_max: Number,
}

/// `{"nurbs": {...}}`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, expecting = "an object")]
pub struct CurveNurbs {
    pub nurbs: Nurbs<Vec3>,
}

/// `{"nurbs": {...}}` of a surface.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, expecting = "an object")]
pub struct Ruled {
    pub nurbs: Surface,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, expecting = "an object")]
pub struct Element {
    pub point: Vec3,
    pub ruling: Vec3,
    pub side: Vec3,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, expecting = "an object")]
pub struct Strip {
    pub t_min: Number,
    pub t_max: Number,
}

/// One of `transition`, `ruled`, `tangent_surface`, and the sheet's options.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, expecting = "an object")]
pub struct Sheet {
    pub transition: Option<Transition>,
    pub ruled: Option<Ruled>,
    pub tangent_surface: Option<TangentSurface>,
    pub thickness: Option<Positive>,
    pub k_factor: Option<Number>,
    pub tolerance: Option<Positive>,
    pub reference: Option<ReferenceName>,
    pub flat_tolerance: Option<Positive>,
    pub max_pieces: Option<Count<2, MAX_PIECES>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, expecting = "an object")]
pub struct Transition {
    pub bottom: ClosedCurve,
    pub top: ClosedCurve,
}

/// One of `polygon`, `circle`, `obround`, `nurbs`: a closed planar curve in space.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, expecting = "an object")]
pub struct ClosedCurve {
    pub polygon: Option<Bounded<Vec3, Corners>>,
    pub circle: Option<SpaceCircle>,
    pub obround: Option<Obround>,
    pub nurbs: Option<Nurbs<Vec3>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, expecting = "an object")]
pub struct SpaceCircle {
    pub center: Vec3,
    pub normal: Vec3,
    pub radius: Positive,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, expecting = "an object")]
pub struct Obround {
    pub center: Vec3,
    pub normal: Vec3,
    pub direction: Vec3,
    pub length: Positive,
    pub radius: Positive,
}

/// A spine method by its name (`"ph-rmf"`, `"frenet"`, `"mobius"`, `"rrmf"`).
#[derive(Clone, Copy, Debug)]
pub struct MethodName(pub SpineMethod);

impl<'de> Deserialize<'de> for MethodName {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(NameVisitor {
            what: "method",
            names: &SpineMethod::ALL.map(|m| (m.name(), m)),
        })
        .map(MethodName)
    }
}

/// How a pipe is swept: `"rmf"` or `"lightest"`.
#[derive(Clone, Copy, Debug)]
pub struct PipeFrameName(pub PipeFrame);

impl<'de> Deserialize<'de> for PipeFrameName {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(NameVisitor {
            what: "pipe frame",
            names: &[("rmf", PipeFrame::Rmf), ("lightest", PipeFrame::Lightest)],
        })
        .map(PipeFrameName)
    }
}

/// `"inner"`, `"neutral"` or `"outer"`.
#[derive(Clone, Copy, Debug)]
pub struct ReferenceName(pub Reference);

impl<'de> Deserialize<'de> for ReferenceName {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(NameVisitor {
            what: "reference",
            names: &[
                ("inner", Reference::Inner),
                ("neutral", Reference::Neutral),
                ("outer", Reference::Outer),
            ],
        })
        .map(ReferenceName)
    }
}

/// `"round"`, `"miter"` or `{"round": {"radius": r}}` (no radius: the default).
#[derive(Clone, Copy, Debug)]
pub struct CornerName(pub Corner);

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, expecting = "an object")]
struct Round {
    radius: Option<Positive>,
}

struct CornerVisitor;

impl<'de> Visitor<'de> for CornerVisitor {
    type Value = Corner;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("\"round\", \"miter\" or {\"round\": {\"radius\": r}}")
    }

    fn visit_str<E: de::Error>(self, name: &str) -> Result<Corner, E> {
        match name {
            "round" => Ok(Corner::Round(None)),
            "miter" => Ok(Corner::Miter),
            other => Err(E::custom(format!(
                "unknown corner \"{other}\"; expected round or miter"
            ))),
        }
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Corner, A::Error> {
        let mut corner = None;
        while let Some(key) = map.next_key::<String>()? {
            if key != "round" {
                return Err(de::Error::unknown_field(&key, &["round"]));
            }
            if corner.is_some() {
                return Err(de::Error::duplicate_field("round"));
            }
            let round: Round = map.next_value()?;
            corner = Some(Corner::Round(round.radius.map(|r| r.0)));
        }
        corner.ok_or_else(|| de::Error::custom("needs one of round"))
    }
}

impl<'de> Deserialize<'de> for CornerName {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(CornerVisitor).map(CornerName)
    }
}

/// `"rmf"`, `"frenet"`, `{"fixed": [x, y, z]}` (a direction, not zero) or `{"guide":
/// [edges]}` (edges of the form of `"wire"`'s, turned into the library's by `job`).
#[derive(Debug)]
pub enum FrameName {
    /// A frame law that needs no curve: the RMF, Frenet, a fixed direction.
    Law(SweepFrame),
    /// The guide curve's edges as given.
    Guide(Vec<Edge>),
}

const FRAME_FORMS: &str = "rmf, frenet, {\"fixed\": [x, y, z]} or {\"guide\": [edges]}";

struct FrameVisitor;

impl<'de> Visitor<'de> for FrameVisitor {
    type Value = FrameName;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("\"rmf\", \"frenet\", {\"fixed\": [x, y, z]} or {\"guide\": [edges]}")
    }

    fn visit_str<E: de::Error>(self, name: &str) -> Result<FrameName, E> {
        match name {
            "rmf" => Ok(FrameName::Law(SweepFrame::Rmf)),
            "frenet" => Ok(FrameName::Law(SweepFrame::Frenet)),
            other => Err(E::custom(format!(
                "unknown frame \"{other}\"; expected {FRAME_FORMS}"
            ))),
        }
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<FrameName, A::Error> {
        let mut frame = None;
        let mut given: Option<String> = None;
        while let Some(key) = map.next_key::<String>()? {
            match &given {
                Some(first) if *first == key => {
                    return Err(de::Error::custom(format!("duplicate field `{key}`")));
                }
                Some(first) => {
                    return Err(de::Error::custom(format!(
                        "{key} beside {first}: give one of fixed, guide"
                    )));
                }
                None => given = Some(key.clone()),
            }
            frame = Some(match key.as_str() {
                "fixed" => FrameName::Law(SweepFrame::Fixed(map.next_value::<FixedDirection>()?.0)),
                "guide" => FrameName::Guide(map.next_value::<Bounded<Edge, Edges>>()?.into_vec()),
                _ => return Err(de::Error::unknown_field(&key, &["fixed", "guide"])),
            });
        }
        frame.ok_or_else(|| de::Error::custom("needs one of fixed, guide"))
    }
}

impl<'de> Deserialize<'de> for FrameName {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(FrameVisitor)
    }
}

/// The direction of a fixed frame: `[x, y, z]`, not zero.
struct FixedDirection(DVec3);

impl<'de> Deserialize<'de> for FixedDirection {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let Vec3(v) = Vec3::deserialize(d)?;
        if v == DVec3::ZERO {
            return Err(de::Error::custom(
                "must not be zero (the direction f2 follows)",
            ));
        }
        Ok(FixedDirection(v))
    }
}

/// `[start, end]`: the profile's scale at the wire's ends, both positive.
#[derive(Clone, Copy, Debug)]
pub struct Scale(pub [f64; 2]);

struct ScaleVisitor;

impl<'de> Visitor<'de> for ScaleVisitor {
    type Value = [f64; 2];

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("[start, end] (two positive numbers)")
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<[f64; 2], A::Error> {
        let mut scale = [1.0; 2];
        let mut n = 0usize;
        // Numbers past the second are checked and counted, not kept.
        while let Some(Positive(x)) = seq.next_element::<Positive>()? {
            if let Some(slot) = scale.get_mut(n) {
                *slot = x;
            }
            n += 1;
        }
        if n != 2 {
            return Err(de::Error::custom(format!(
                "must be [start, end], got {n} number{}",
                if n == 1 { "" } else { "s" }
            )));
        }
        Ok(scale)
    }
}

impl<'de> Deserialize<'de> for Scale {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(ScaleVisitor).map(Scale)
    }
}

/// `[fraction, scale]`: a knot of the scale law, the fraction of the wire's length in (0, 1)
/// (increasing from knot to knot: checked by the library) and the scale there, positive.
#[derive(Clone, Copy, Debug)]
pub struct ScaleKnot(pub (f64, f64));

struct ScaleKnotVisitor;

/// A fraction of the wire's length (a knot's, a section's): a finite number in (0, 1).
#[derive(Debug)]
pub struct Fraction(pub f64);

impl<'de> Deserialize<'de> for Fraction {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let Number(x) = Number::deserialize(d)?;
        if x > 0.0 && x < 1.0 {
            Ok(Fraction(x))
        } else {
            Err(de::Error::custom(format!(
                "must lie in (0, 1) (a fraction of the wire's length), got {x}"
            )))
        }
    }
}

impl<'de> Visitor<'de> for ScaleKnotVisitor {
    type Value = (f64, f64);

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str(
            "[fraction, scale] (a fraction of the wire's length in (0, 1), a positive scale)",
        )
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<(f64, f64), A::Error> {
        let count = |n: usize| {
            de::Error::custom(format!(
                "must be [fraction, scale], got {n} number{}",
                if n == 1 { "" } else { "s" }
            ))
        };
        let Some(Fraction(at)) = seq.next_element::<Fraction>()? else {
            return Err(count(0));
        };
        let Some(Positive(scale)) = seq.next_element::<Positive>()? else {
            return Err(count(1));
        };
        // Numbers past the second are checked and counted, not kept.
        let mut n = 2;
        while seq.next_element::<Number>()?.is_some() {
            n += 1;
        }
        if n != 2 {
            return Err(count(n));
        }
        Ok((at, scale))
    }
}

impl<'de> Deserialize<'de> for ScaleKnot {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(ScaleKnotVisitor).map(ScaleKnot)
    }
}
