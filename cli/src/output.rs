//! The files the tool writes, chosen by extension, each rendered to memory (the module
//! `write` puts them on disk).

use crate::construct::{Outcome, SheetOutcome};
use crate::job::MeshOptions;
use crate::summary::{json_text, Summary};
use rmfsurf::export::{dxf, obj, openscad, step, svg, vtk};
use rmfsurf::{
    closed_mesh, grid_normals, grid_parameters, sheet::Layer, sheet::Side, tessellate, NurbsCurve,
    NurbsSurface, PiecewiseSurface,
};
use std::path::Path;

/// What a file holds, by its extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    Step,
    /// `NAME.flat.step`: a flat pattern as one planar STEP face.
    StepFlat,
    Vtp,
    Obj,
    Scad,
    Svg,
    Dxf,
    Json,
}

pub const EXTENSIONS: &str = ".step/.stp, .flat.step, .vtp, .obj, .scad, .svg, .dxf, .json";

impl Format {
    pub fn of(path: &Path) -> Option<Self> {
        let extension = path.extension()?.to_str()?.to_ascii_lowercase();
        let flat = path
            .file_stem()
            .is_some_and(|s| s.to_string_lossy().to_ascii_lowercase().ends_with(".flat"));
        Some(match extension.as_str() {
            "step" | "stp" if flat => Format::StepFlat,
            "step" | "stp" => Format::Step,
            "vtp" => Format::Vtp,
            "obj" => Format::Obj,
            "scad" => Format::Scad,
            "svg" => Format::Svg,
            "dxf" => Format::Dxf,
            "json" => Format::Json,
            _ => return None,
        })
    }

    /// Flat patterns exist only for developments (cone splines, sheets).
    pub fn is_pattern(self) -> bool {
        matches!(self, Format::Svg | Format::Dxf | Format::StepFlat)
    }
}

/// The product name written into files: the output's file stem, with control characters
/// (which would end an OBJ or OpenSCAD comment line) replaced.
fn title(path: &Path) -> String {
    path.file_stem()
        .map_or("rmfsurf".into(), |s| s.to_string_lossy())
        .chars()
        .map(|c| if c.is_control() { '_' } else { c })
        .collect()
}

fn surface_of(outcome: &Outcome) -> &PiecewiseSurface {
    match outcome {
        Outcome::Sweep(o) => &o.surface,
        Outcome::ConeSpline(o) => &o.surface,
        Outcome::Wire(_) => unreachable!("wire sweeps are rendered by render_wire"),
        Outcome::Sheet(_) => unreachable!("sheets are rendered by render_sheet"),
    }
}

/// The files of a wire sweep: its STEP solid (or sheet) and the summary.
fn render_wire(
    name: &str,
    format: Format,
    shape: &rmfsurf::wire::Shape,
    summary: &Summary,
) -> rmfsurf::Result<String> {
    match format {
        Format::Step => shape.to_step(name),
        Format::Json => Ok(json_text(summary)),
        _ => Err(rmfsurf::Error::invalid_input(
            "a wire sweep is written as a STEP solid (.step, .stp) and its summary (.json); \
             meshes and flat patterns are not available for it",
        )),
    }
}

/// The files of a sheet-metal part: the formed solid (STEP), the neutral layer's flat
/// pattern (DXF, SVG, planar STEP face), the summary.
fn render_sheet(
    name: &str,
    format: Format,
    outcome: &SheetOutcome,
    summary: &Summary,
) -> rmfsurf::Result<String> {
    Ok(match format {
        Format::Step => outcome.part.to_step(name)?,
        Format::StepFlat => step::flat_to_step(&outcome.flat, name)?,
        Format::Dxf => dxf::pattern_to_dxf(&outcome.flat),
        Format::Svg => svg::pattern_to_svg(name, &outcome.flat),
        Format::Json => json_text(summary),
        Format::Vtp | Format::Obj | Format::Scad => {
            return Err(rmfsurf::Error::invalid_input(
                "a sheet-metal part is written as .step (the formed solid), .flat.step, .dxf, .svg (the flat pattern) or .json",
            ))
        }
    })
}

/// The text of the file `path` in `format`.
pub fn render(
    path: &Path,
    format: Format,
    outcome: &Outcome,
    summary: &Summary,
    mesh: &MeshOptions,
) -> rmfsurf::Result<String> {
    let name = title(path);
    if let Outcome::Wire(shape) = outcome {
        return render_wire(&name, format, shape, summary);
    }
    if let Outcome::Sheet(sheet) = outcome {
        return render_sheet(&name, format, sheet, summary);
    }
    let surface = surface_of(outcome);
    let (u, v) = (mesh.u_steps, mesh.v_steps);
    Ok(match format {
        Format::Step => {
            let nurbs = NurbsSurface::from_piecewise(surface).map_err(|e| {
                rmfsurf::Error::invalid_input(format!(
                    "the surface is not one continuous NURBS ({}); Frenet frames jump at the spine's joints",
                    e.message()
                ))
            })?;
            step::surfaces_to_step(&[&nurbs], &name)?
        }
        Format::Vtp => {
            let m = tessellate(surface, u, v)?;
            vtk::mesh_to_vtp(&m.points, &m.triangles, Some(&grid_normals(surface, u, v)))
        }
        Format::Obj => {
            let m = tessellate(surface, u, v)?;
            obj::mesh_to_obj(
                &name,
                &m.points,
                &m.triangles,
                Some(&grid_normals(surface, u, v)),
            )
        }
        Format::Scad => {
            let solid =
                closed_mesh(surface, u, v, mesh.thickness).map_err(|e| match mesh.thickness {
                    None => rmfsurf::Error::invalid_input(format!(
                        "{} (give mesh.thickness)",
                        e.message()
                    )),
                    Some(_) => e,
                })?;
            let placements = match outcome {
                Outcome::Sweep(o) => Some(
                    grid_parameters(o.surface.v_breaks(), v)
                        .into_iter()
                        .map(|t| (o.framed.curve().eval(t), o.framed.frames().frame(t)))
                        .collect::<Vec<_>>(),
                ),
                Outcome::ConeSpline(_) | Outcome::Wire(_) | Outcome::Sheet(_) => None,
            };
            openscad::solid_to_scad(&name, &solid, placements.as_deref())
        }
        Format::Svg | Format::Dxf | Format::StepFlat => {
            let Outcome::ConeSpline(o) = outcome else {
                unreachable!("checked before the construction")
            };
            match format {
                Format::Svg => svg::pattern_to_svg(&name, &o.pattern),
                Format::Dxf => dxf::pattern_to_dxf(&o.pattern),
                _ => step::flat_to_step(&o.pattern, &name)?,
            }
        }
        Format::Json => json_text(summary),
    })
}

/// The curves of `--curves`: the spine of a sweep, the two boundary arc splines of a cone
/// spline strip.
pub fn render_curves(path: &Path, outcome: &Outcome) -> rmfsurf::Result<String> {
    let curves = match outcome {
        Outcome::Sweep(o) => vec![NurbsCurve::from_piecewise(o.framed.curve())?],
        Outcome::Wire(shape) => shape
            .spine()
            .iter()
            .map(NurbsCurve::from_piecewise)
            .collect::<rmfsurf::Result<Vec<_>>>()?,
        Outcome::ConeSpline(o) => vec![
            NurbsCurve::from_piecewise(&o.spline.boundary(o.t_min)?)?,
            NurbsCurve::from_piecewise(&o.spline.boundary(o.t_max)?)?,
        ],
        Outcome::Sheet(o) => [Side::First, Side::Second]
            .iter()
            .map(|&side| NurbsCurve::from_piecewise(&o.part.boundary(Layer::Reference, side)?))
            .collect::<rmfsurf::Result<Vec<_>>>()?,
    };
    step::curves_to_step(&curves.iter().collect::<Vec<_>>(), &title(path))
}
