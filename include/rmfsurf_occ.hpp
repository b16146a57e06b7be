// rmfsurf_occ.hpp — header-only: an OpenCascade shape built from the library's boundary
// representation (RmfBrep: rmf_shape_brep for a wire sweep, rmf_sheet_part_brep for a
// sheet-metal part) with BRep_Builder, as the kernel holds it: one TopoDS_Edge per shared
// edge with its curve on each face, seams as seams, degenerate edges at cone apices, the
// loops and faces' senses as the library made them. No sewing, no STEP file, no ShapeFix:
// the result is valid for BRepCheck_Analyzer as built. Faces the library marks analytic
// (rmf_brep_face_analytic) are built on OpenCascade's own planes, cylinders, cones and tori, their
// edges as lines and circles (rmf_brep_edge_analytic).
//
//     #include "rmfsurf_occ.hpp"
//     RmfBrep *brep = nullptr;
//     if (rmf_shape_brep(shape, &brep) == RMF_OK) {
//         TopoDS_Shape solid = rmfsurf::occ::build(brep);   // throws rmfsurf::occ::Error
//         rmf_brep_free(brep);
//     }
//
// Link OpenCascade's TKBRep, TKG2d, TKG3d, TKGeomBase, TKMath and TKernel (and librmfsurf).
#pragma once

#include "rmfsurf.h"

#include <BRep_Builder.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom2d_Line.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_Circle.hxx>
#include <Geom_ConicalSurface.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_Line.hxx>
#include <Geom_Plane.hxx>
#include <Geom_ToroidalSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Ax3.hxx>

#include <stdexcept>
#include <string>
#include <vector>

namespace rmfsurf {
namespace occ {

/// A B-rep the builder could not read (the library's status and message).
class Error : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

namespace detail {

inline void check(RmfStatus status, const char *call) {
    if (status != RMF_OK) throw Error(std::string(call) + ": " + rmf_last_error());
}

/// Distinct knots and their multiplicities (OpenCascade's form of a knot vector).
struct Knots {
    TColStd_Array1OfReal values;
    TColStd_Array1OfInteger multiplicities;
};

inline Knots knots(const double *k, size_t n) {
    size_t distinct = 0;
    for (size_t i = 0; i < n; ++i)
        if (i == 0 || k[i] != k[i - 1]) ++distinct;
    Knots out{TColStd_Array1OfReal(1, (int)distinct), TColStd_Array1OfInteger(1, (int)distinct)};
    int at = 0;
    for (size_t i = 0; i < n; ++i) {
        if (i == 0 || k[i] != k[i - 1]) {
            out.values(++at) = k[i];
            out.multiplicities(at) = 0;
        }
        out.multiplicities(at) += 1;
    }
    return out;
}

inline Handle(Geom_BSplineCurve) curve(const RmfNurbsCurve &c) {
    const int n = (int)c.pole_count;
    TColgp_Array1OfPnt poles(1, n);
    TColStd_Array1OfReal weights(1, n);
    for (int i = 0; i < n; ++i) {
        poles(i + 1) = gp_Pnt(c.poles[i].x, c.poles[i].y, c.poles[i].z);
        weights(i + 1) = c.weights[i];
    }
    const Knots k = knots(c.knots, c.knot_count);
    return new Geom_BSplineCurve(poles, weights, k.values, k.multiplicities, (int)c.degree);
}

inline Handle(Geom2d_BSplineCurve) curve_2d(const RmfNurbsCurve &c) {
    const int n = (int)c.pole_count;
    TColgp_Array1OfPnt2d poles(1, n);
    TColStd_Array1OfReal weights(1, n);
    for (int i = 0; i < n; ++i) {
        poles(i + 1) = gp_Pnt2d(c.poles[i].x, c.poles[i].y);
        weights(i + 1) = c.weights[i];
    }
    const Knots k = knots(c.knots, c.knot_count);
    return new Geom2d_BSplineCurve(poles, weights, k.values, k.multiplicities, (int)c.degree);
}

/// origin + t · direction on [first, last], as a degree-1 B-spline: a Geom2d_Line would
/// run at unit speed, the library's lines need not.
inline Handle(Geom2d_BSplineCurve) line_2d(RmfVec2 origin, RmfVec2 direction, double first, double last) {
    TColgp_Array1OfPnt2d poles(1, 2);
    poles(1) = gp_Pnt2d(origin.x + first * direction.x, origin.y + first * direction.y);
    poles(2) = gp_Pnt2d(origin.x + last * direction.x, origin.y + last * direction.y);
    TColStd_Array1OfReal values(1, 2);
    TColStd_Array1OfInteger multiplicities(1, 2);
    values(1) = first;
    values(2) = last;
    multiplicities(1) = multiplicities(2) = 2;
    return new Geom2d_BSplineCurve(poles, values, multiplicities, 1);
}

inline Handle(Geom_Surface) surface(const RmfBrepFace &f) {
    if (f.kind == RMF_BREP_SURFACE_PLANE) {
        const gp_Ax3 axes(gp_Pnt(f.plane_origin.x, f.plane_origin.y, f.plane_origin.z),
                          gp_Dir(f.plane_normal.x, f.plane_normal.y, f.plane_normal.z),
                          gp_Dir(f.plane_x_axis.x, f.plane_x_axis.y, f.plane_x_axis.z));
        return new Geom_Plane(axes);
    }
    const RmfNurbsSurface &s = f.nurbs;
    const int nu = (int)s.pole_count_u, nv = (int)s.pole_count_v;
    TColgp_Array2OfPnt poles(1, nu, 1, nv);
    TColStd_Array2OfReal weights(1, nu, 1, nv);
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const RmfVec3 &p = s.poles[(size_t)i * nv + j];
            poles(i + 1, j + 1) = gp_Pnt(p.x, p.y, p.z);
            weights(i + 1, j + 1) = s.weights[(size_t)i * nv + j];
        }
    const Knots ku = knots(s.knots_u, s.knot_count_u), kv = knots(s.knots_v, s.knot_count_v);
    return new Geom_BSplineSurface(poles, weights, ku.values, kv.values, ku.multiplicities, kv.multiplicities,
                                   (int)s.degree_u, (int)s.degree_v);
}

inline gp_Pnt point(RmfVec3 p) { return gp_Pnt(p.x, p.y, p.z); }

inline gp_Dir direction(RmfVec3 d) { return gp_Dir(d.x, d.y, d.z); }

/// A line or circle on its length or angle (rmf_brep_edge_analytic); null otherwise.
inline Handle(Geom_Curve) analytic_curve(const RmfBrepAnalytic &a) {
    if (a.kind == RMF_ANALYTIC_LINE) return new Geom_Line(point(a.location), direction(a.axis));
    if (a.kind == RMF_ANALYTIC_CIRCLE)
        return new Geom_Circle(gp_Ax2(point(a.location), direction(a.axis), direction(a.x_axis)), a.radius);
    return Handle(Geom_Curve)();
}

/// A plane, cylinder, cone or torus (rmf_brep_face_analytic); null otherwise.
inline Handle(Geom_Surface) analytic_surface(const RmfBrepAnalytic &a) {
    if (a.kind != RMF_ANALYTIC_PLANE && a.kind != RMF_ANALYTIC_CYLINDER && a.kind != RMF_ANALYTIC_CONE &&
        a.kind != RMF_ANALYTIC_TORUS)
        return Handle(Geom_Surface)();
    const gp_Ax3 axes(point(a.location), direction(a.axis), direction(a.x_axis));
    if (a.kind == RMF_ANALYTIC_PLANE) return new Geom_Plane(axes);
    if (a.kind == RMF_ANALYTIC_CYLINDER) return new Geom_CylindricalSurface(axes, a.radius);
    if (a.kind == RMF_ANALYTIC_CONE) return new Geom_ConicalSurface(axes, a.semi_angle, a.radius);
    if (a.kind == RMF_ANALYTIC_TORUS) return new Geom_ToroidalSurface(axes, a.radius, a.minor_radius);
    return Handle(Geom_Surface)();
}

inline Handle(Geom2d_Curve) pcurve(const RmfBrepUse &u, double first, double last, bool analytic) {
    // On an analytic surface: a parameter line of unit speed on the edge's length or angle.
    if (analytic && u.pcurve_kind == RMF_PCURVE_LINE)
        return new Geom2d_Line(gp_Pnt2d(u.line_origin.x, u.line_origin.y),
                               gp_Dir2d(u.line_direction.x, u.line_direction.y));
    if (u.pcurve_kind == RMF_PCURVE_LINE) return line_2d(u.line_origin, u.line_direction, first, last);
    if (u.pcurve_kind == RMF_PCURVE_NURBS) return curve_2d(u.pcurve);
    return Handle(Geom2d_Curve)();
}

/// Whether a face is its whole B-spline surface: one loop, every pcurve a line along the
/// boundary of the parameter rectangle. The kernel then integrates over the rectangle.
inline bool natural_bounds(const RmfBrepFace &f, const std::vector<RmfBrepUse> &uses, size_t loops) {
    if (f.kind != RMF_BREP_SURFACE_NURBS || loops != 1) return false;
    const double u0 = f.nurbs.knots_u[0], u1 = f.nurbs.knots_u[f.nurbs.knot_count_u - 1];
    const double v0 = f.nurbs.knots_v[0], v1 = f.nurbs.knots_v[f.nurbs.knot_count_v - 1];
    for (const RmfBrepUse &u : uses) {
        if (u.pcurve_kind != RMF_PCURVE_LINE) return false;
        const bool along_u = u.line_direction.x == 0 && (u.line_origin.x == u0 || u.line_origin.x == u1);
        const bool along_v = u.line_direction.y == 0 && (u.line_origin.y == v0 || u.line_origin.y == v1);
        if (!along_u && !along_v) return false;
    }
    return true;
}

} // namespace detail

/// The OpenCascade shape of a B-rep: a TopoDS_Solid for a solid (of all its shells: a
/// cavity's walls are shells too), else its TopoDS_Shell (a TopoDS_Compound of shells when
/// it has several). Throws Error if the B-rep cannot be read.
inline TopoDS_Shape build(const RmfBrep *brep) {
    using detail::check;
    RmfBrepCounts counts;
    check(rmf_brep_counts(brep, &counts), "rmf_brep_counts");
    const double tolerance = counts.tolerance;
    BRep_Builder builder;
    std::vector<TopoDS_Vertex> vertices(counts.vertex_count);
    for (size_t i = 0; i < counts.vertex_count; ++i) {
        RmfVec3 p;
        check(rmf_brep_vertex(brep, i, &p), "rmf_brep_vertex");
        builder.MakeVertex(vertices[i], gp_Pnt(p.x, p.y, p.z), tolerance);
    }
    std::vector<TopoDS_Edge> edges(counts.edge_count);
    std::vector<std::pair<double, double>> ranges(counts.edge_count);
    std::vector<bool> exact_edge(counts.edge_count, false);
    for (size_t i = 0; i < counts.edge_count; ++i) {
        RmfBrepEdge e;
        check(rmf_brep_edge(brep, i, &e), "rmf_brep_edge");
        if (e.start >= counts.vertex_count || e.end >= counts.vertex_count)
            throw Error("edge " + std::to_string(i) + " joins vertices that do not exist");
        RmfBrepAnalytic analytic;
        check(rmf_brep_edge_analytic(brep, i, &analytic), "rmf_brep_edge_analytic");
        const Handle(Geom_Curve) exact = detail::analytic_curve(analytic);
        ranges[i] = {e.curve.knots[0], e.curve.knots[e.curve.knot_count - 1]};
        if (e.degenerate) {
            builder.MakeEdge(edges[i]);
            builder.Degenerated(edges[i], Standard_True);
        } else if (!exact.IsNull()) {
            exact_edge[i] = true;
            ranges[i] = {0.0, analytic.end};
            builder.MakeEdge(edges[i], exact, tolerance);
            // A line is unbounded: its range before its curves on the faces are added.
            builder.Range(edges[i], 0.0, analytic.end);
        } else {
            builder.MakeEdge(edges[i], detail::curve(e.curve), tolerance);
        }
        builder.Add(edges[i], vertices[e.start].Oriented(TopAbs_FORWARD));
        builder.Add(edges[i], vertices[e.end].Oriented(TopAbs_REVERSED));
    }
    std::vector<TopoDS_Face> faces(counts.face_count);
    for (size_t f = 0; f < counts.face_count; ++f) {
        RmfBrepFace face;
        check(rmf_brep_face(brep, f, &face), "rmf_brep_face");
        RmfBrepAnalytic analytic;
        check(rmf_brep_face_analytic(brep, f, &analytic), "rmf_brep_face_analytic");
        const Handle(Geom_Surface) exact = detail::analytic_surface(analytic);
        const bool on_exact = !exact.IsNull();
        TopoDS_Face &made = faces[f];
        builder.MakeFace(made, on_exact ? exact : detail::surface(face), tolerance);
        std::vector<RmfBrepUse> all;
        for (size_t l = 0; l < face.loop_count; ++l) {
            RmfBrepLoop bound;
            check(rmf_brep_loop(brep, f, l, &bound), "rmf_brep_loop");
            TopoDS_Wire wire;
            builder.MakeWire(wire);
            for (size_t k = 0; k < bound.use_count; ++k) {
                RmfBrepUse u;
                // On the analytic surface, the loop as it runs there (with its curves).
                if (on_exact)
                    check(rmf_brep_analytic_use(brep, f, l, k, &u), "rmf_brep_analytic_use");
                else
                    check(rmf_brep_use(brep, f, l, k, &u), "rmf_brep_use");
                if (u.edge >= counts.edge_count)
                    throw Error("face " + std::to_string(f) + " uses edge " + std::to_string(u.edge) + " of " +
                                std::to_string(counts.edge_count));
                builder.Add(wire, edges[u.edge].Oriented(u.forward ? TopAbs_FORWARD : TopAbs_REVERSED));
                all.push_back(u);
            }
            wire.Closed(Standard_True);
            builder.Add(made, wire);
        }
        // Each edge's curve on this face: a seam (used both ways) carries two, the forward
        // use's first.
        for (size_t k = 0; k < all.size(); ++k) {
            const RmfBrepUse &u = all[k];
            // A line or circle on a plane: the kernel projects it (the model's curve on the
            // plane is on the NURBS edge's parameter).
            if (exact_edge[u.edge] && !on_exact) continue;
            const auto [first, last] = ranges[u.edge];
            const Handle(Geom2d_Curve) on_face = detail::pcurve(u, first, last, on_exact);
            if (on_face.IsNull()) continue;
            size_t twin = all.size();
            for (size_t j = 0; j < all.size(); ++j)
                if (j != k && all[j].edge == u.edge) twin = j;
            if (twin == all.size()) {
                builder.UpdateEdge(edges[u.edge], on_face, made, tolerance);
            } else if (u.forward && !all[twin].forward) {
                builder.UpdateEdge(edges[u.edge], on_face, detail::pcurve(all[twin], first, last, on_exact), made,
                                   tolerance);
            }
        }
        if (!on_exact && detail::natural_bounds(face, all, face.loop_count))
            builder.NaturalRestriction(made, Standard_True);
        if (!(on_exact ? analytic.same_sense : face.same_sense)) made.Reverse();
    }
    for (size_t i = 0; i < counts.edge_count; ++i) {
        builder.Range(edges[i], ranges[i].first, ranges[i].second);
        builder.SameParameter(edges[i], Standard_True);
        builder.SameRange(edges[i], Standard_True);
    }
    std::vector<TopoDS_Shell> shells(counts.shell_count);
    for (size_t s = 0; s < counts.shell_count; ++s) {
        RmfBrepShell shell;
        check(rmf_brep_shell(brep, s, &shell), "rmf_brep_shell");
        builder.MakeShell(shells[s]);
        for (size_t k = 0; k < shell.face_count; ++k) builder.Add(shells[s], faces[shell.faces[k]]);
        shells[s].Closed(counts.solid != 0);
    }
    if (counts.solid) {
        // The outer shell and, for a hollow profile swept round a closed wire, the walls of
        // the cavity: closed shells of one solid, their faces facing out of the material.
        TopoDS_Solid solid;
        builder.MakeSolid(solid);
        for (const TopoDS_Shell &shell : shells) builder.Add(solid, shell);
        return solid;
    }
    if (counts.shell_count == 1) return shells[0];
    TopoDS_Compound compound;
    builder.MakeCompound(compound);
    for (const TopoDS_Shell &shell : shells) builder.Add(compound, shell);
    return compound;
}

} // namespace occ
} // namespace rmfsurf
