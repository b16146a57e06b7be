// An OpenCascade kernel taking rmfsurf's wire sweeps: the wire is swept through the C API
// (rmf_wire_sweep), written with rmf_shape_write_step and read back by OpenCascade's own
// STEP reader, handed over in OpenCascade's B-rep text (rmf_shape_occ_brep, built by
// BRepTools::Read from a string, no file), and built from the library's B-rep model with
// BRep_Builder (rmf_shape_brep and include/rmfsurf_occ.hpp: no text, no sewing), then
// checked by OpenCascade — one Solid, BRepCheck_Analyzer valid, a boolean with a box
// (common and cut: valid, their volumes adding up to the solid's), the volume
// by BRepGProp's adaptive integration against the closed form, the parameter lines of every
// face (GeomAdaptor D1) — and printed beside OpenCascade's own sweep of the same wire
// (BRepOffsetAPI_MakePipeShell in corrected-Frenet and Frenet mode, right or round corners),
// measured by the same code. rmfsurf's figures are checked (the program fails on any);
// OpenCascade's are reported. A square-to-round sheet-metal part (rmf_sheet_part_transition)
// is built both ways too (rmf_sheet_part_brep).
//
// Built and run by the test command (integration/tests/opencascade.rs): C++17 against
// include/rmfsurf.h and librmfsurf, with OpenCascade's TKSTEP, TKXSBase, TKOffset (the
// sweep), TKTopAlgo, TKBRep and the foundation toolkits.
#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Common.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBndLib.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <Bnd_Box.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "rmfsurf.h"
#include "rmfsurf_occ.hpp"
#include "wire_sweep.hpp"

using wire_sweep::Edge;
using wire_sweep::Kind;
using wire_sweep::Measure;
using wire_sweep::Profile;

static int failures = 0;
static const double PI = 3.14159265358979323846;

static void check(bool ok, const char *what, double value, double limit) {
    std::printf("  %-70s %10.3e  (limit %.0e)%s\n", what, value, limit, ok ? "" : "  FAILED");
    if (!ok) failures++;
}

static void require(bool ok, const char *what) {
    std::printf("  %-70s %s\n", what, ok ? "yes" : "NO  FAILED");
    if (!ok) failures++;
}

static Edge line(gp_Pnt a, gp_Pnt b) {
    Edge e;
    e.kind = Kind::Line;
    e.p[0] = a, e.p[1] = b;
    return e;
}

static Edge arc(gp_Pnt a, gp_Pnt m, gp_Pnt b) {
    Edge e;
    e.kind = Kind::Arc;
    e.p[0] = a, e.p[1] = m, e.p[2] = b;
    return e;
}

static RmfVec3 v3(const gp_Pnt &p) { return RmfVec3{p.X(), p.Y(), p.Z()}; }

/// The same wire for the C API (curve edges made with rmf_nurbs_curve_create).
struct CWire {
    std::vector<RmfEdge> edges;
    std::vector<RmfCurve *> curves;
    explicit CWire(const std::vector<Edge> &wire) {
        for (const Edge &e : wire) {
            RmfEdge c{};
            if (e.kind == Kind::Nurbs) {
                std::vector<RmfVec3> poles;
                for (const gp_Pnt &p : e.poles) poles.push_back(v3(p));
                RmfCurve *curve = nullptr;
                if (rmf_nurbs_curve_create((uint32_t)e.degree, poles.data(), e.weights.empty() ? nullptr : e.weights.data(),
                                           poles.size(), e.knots.data(), e.knots.size(), &curve) != RMF_OK)
                    std::printf("rmf_nurbs_curve_create: %s\n", rmf_last_error());
                curves.push_back(curve);
                c.kind = RMF_EDGE_CURVE;
                c.curve = curve;
            } else {
                c.kind = e.kind == Kind::Line ? RMF_EDGE_LINE : RMF_EDGE_ARC;
                for (int i = 0; i < 3; ++i) c.points[i] = v3(e.p[i]);
            }
            edges.push_back(c);
        }
    }
    ~CWire() {
        for (RmfCurve *c : curves) rmf_curve_free(c);
    }
};

static RmfCurve *c_profile(const Profile &p) {
    RmfCurve *c = nullptr;
    const double a = p.size, s = 0.70710678118654752440;
    if (p.circle) {
        const RmfVec3 poles[9] = {{a, 0, 0},   {a, a, 0},   {0, a, 0},  {-a, a, 0}, {-a, 0, 0},
                                  {-a, -a, 0}, {0, -a, 0}, {a, -a, 0}, {a, 0, 0}};
        const double w[9] = {1, s, 1, s, 1, s, 1, s, 1}, k[12] = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
        rmf_nurbs_curve_create(2, poles, w, 9, k, 12, &c);
    } else {
        const RmfVec3 poles[5] = {{a, a, 0}, {-a, a, 0}, {-a, -a, 0}, {a, -a, 0}, {a, a, 0}};
        const double k[7] = {0, 0, 1, 2, 3, 4, 4};
        rmf_nurbs_curve_create(1, poles, nullptr, 5, k, 7, &c);
    }
    return c;
}

/// The largest |cos| between parameter lines over the lateral faces of a shape that lie
/// along the given spine edges (all when `edges` is empty), from the NURBS views as
/// OpenCascade Geom_BSplineSurfaces.
static double c_face_cosine(const RmfShape *shape, const std::vector<size_t> &edges) {
    double worst = 0;
    for (size_t f = 0; f < rmf_shape_face_count(shape); ++f) {
        RmfShapeFace face;
        RmfNurbsSurface v;
        rmf_shape_face(shape, f, &face);
        if (face.kind != RMF_FACE_SWEPT) continue;
        bool wanted = edges.empty();
        for (size_t e : edges) wanted = wanted || e == face.spine_edge;
        if (!wanted || rmf_surface_nurbs(face.surface, &v) != RMF_OK) continue;
        TColgp_Array2OfPnt poles(1, (int)v.pole_count_u, 1, (int)v.pole_count_v);
        TColStd_Array2OfReal weights(1, (int)v.pole_count_u, 1, (int)v.pole_count_v);
        for (size_t i = 0; i < v.pole_count_u; ++i)
            for (size_t j = 0; j < v.pole_count_v; ++j) {
                const RmfVec3 p = v.poles[i * v.pole_count_v + j];
                poles((int)i + 1, (int)j + 1) = gp_Pnt(p.x, p.y, p.z);
                weights((int)i + 1, (int)j + 1) = v.weights[i * v.pole_count_v + j];
            }
        auto distinct = [](const double *k, size_t n, TColStd_Array1OfReal *&knots, TColStd_Array1OfInteger *&mults) {
            std::vector<double> d;
            std::vector<int> m;
            for (size_t i = 0; i < n; ++i)
                if (!d.empty() && k[i] == d.back())
                    m.back()++;
                else
                    d.push_back(k[i]), m.push_back(1);
            knots = new TColStd_Array1OfReal(1, (int)d.size());
            mults = new TColStd_Array1OfInteger(1, (int)d.size());
            for (size_t i = 0; i < d.size(); ++i) (*knots)((int)i + 1) = d[i], (*mults)((int)i + 1) = m[i];
        };
        TColStd_Array1OfReal *ku, *kv;
        TColStd_Array1OfInteger *mu, *mv;
        distinct(v.knots_u, v.knot_count_u, ku, mu);
        distinct(v.knots_v, v.knot_count_v, kv, mv);
        Handle(Geom_BSplineSurface) s =
            new Geom_BSplineSurface(poles, weights, *ku, *kv, *mu, *mv, (int)v.degree_u, (int)v.degree_v);
        delete ku, delete kv, delete mu, delete mv;
        worst = std::max(worst, wire_sweep::face_cosine(BRepBuilderAPI_MakeFace(s, 1e-9).Face()));
    }
    return worst;
}

/// The shape's OpenCascade B-rep text (rmf_shape_occ_brep: the size, then the text).
static std::string occ_text(const RmfShape *shape) {
    size_t length = 0;
    require(rmf_shape_occ_brep(shape, nullptr, 0, &length) == RMF_OK, "rmf_shape_occ_brep (size)");
    std::string text(length + 1, '\0');
    require(rmf_shape_occ_brep(shape, text.data(), text.size(), &length) == RMF_OK, "rmf_shape_occ_brep");
    text.resize(length);
    return text;
}

/// The shape's OpenCascade binary B-rep for BinTools::Read (rmf_shape_occ_binary: the size,
/// then the file).
static std::string occ_binary(const RmfShape *shape) {
    size_t length = 0;
    require(rmf_shape_occ_binary(shape, RMF_OCC_READER_BINTOOLS, nullptr, 0, &length) == RMF_OK,
            "rmf_shape_occ_binary (size)");
    std::string bytes(length, '\0');
    require(rmf_shape_occ_binary(shape, RMF_OCC_READER_BINTOOLS, reinterpret_cast<uint8_t *>(bytes.data()),
                                 bytes.size(), &length) == RMF_OK,
            "rmf_shape_occ_binary");
    return bytes;
}

/// The same shape from the binary B-rep as from the text: valid, one solid, the same faces
/// and poles, the volume to 1e-12 (the same numbers, read without parsing).
static void check_binary(const std::string &bytes, const Measure &from_text, const char *what) {
    const Measure binary = wire_sweep::measure(wire_sweep::read_brep_binary(bytes));
    require(binary.valid && binary.solids == 1, what);
    require(binary.bspline_faces == from_text.bspline_faces && binary.analytic_faces == from_text.analytic_faces &&
                binary.bspline_poles == from_text.bspline_poles,
            "the binary B-rep's faces and poles are the text's");
    check(std::fabs(binary.volume - from_text.volume) <= 1e-12 * from_text.volume,
          "volume from the binary B-rep against the text's, relative",
          std::fabs(binary.volume - from_text.volume) / from_text.volume, 1e-12);
}

/// The shape built by BRep_Builder from the library's B-rep model (rmfsurf_occ.hpp).
static TopoDS_Shape from_model(const RmfShape *shape) {
    RmfBrep *brep = nullptr;
    require(rmf_shape_brep(shape, &brep) == RMF_OK, "rmf_shape_brep");
    const TopoDS_Shape built = rmfsurf::occ::build(brep);
    rmf_brep_free(brep);
    return built;
}

/// OpenCascade's booleans on a solid: the part of it inside a box holding the lower 37 % of
/// its bounding box in y and the rest, both valid, together its volume to 1e-8 relative
/// (OpenCascade integrates the parts' trimmed faces to about 1e-9; a wrong boolean is off by
/// far more). The box's face avoids the middle, where a symmetric part's seam ruling lies
/// in it: OpenCascade's boolean fails there on the hopper, from its own reading of the
/// B-rep text as from the model.
static void check_boolean(const TopoDS_Shape &solid, double volume) {
    const double limit = 1e-8;
    Bnd_Box bounds;
    BRepBndLib::Add(solid, bounds);
    double x0, y0, z0, x1, y1, z1;
    bounds.Get(x0, y0, z0, x1, y1, z1);
    const double margin = 1 + (x1 - x0) + (y1 - y0) + (z1 - z0);
    const TopoDS_Shape box =
        BRepPrimAPI_MakeBox(gp_Pnt(x0 - margin, y0 - margin, z0 - margin),
                            gp_Pnt(x1 + margin, y0 + 0.37 * (y1 - y0), z1 + margin))
            .Shape();
    const TopoDS_Shape inside = BRepAlgoAPI_Common(solid, box).Shape();
    const TopoDS_Shape outside = BRepAlgoAPI_Cut(solid, box).Shape();
    const Measure a = wire_sweep::measure(inside), b = wire_sweep::measure(outside);
    require(a.valid && b.valid && a.volume > 0 && b.volume > 0,
            "a box's common with the solid and the solid cut by it: valid, both parts");
    check(std::fabs(a.volume + b.volume - volume) <= limit * volume,
          "the two parts' volumes against the solid's, relative", std::fabs(a.volume + b.volume - volume) / volume,
          limit);
}

/// One wire: rmfsurf's solid through STEP into OpenCascade, checked; OpenCascade's sweeps.
struct Case {
    const char *name;
    std::vector<Edge> wire;
    Profile profile;
    RmfCorner corner;
    double corner_radius;
    gp_Dir f2;       // f2 at the start, for both
    double exact;    // the closed-form volume (0: none)
    double cos_limit;
    std::vector<size_t> curve_edges;  // NURBS edges (their faces: |cos| ≤ 1e-6)
    uint32_t closure;
};

static void run(const Case &c) {
    std::printf("%s\n", c.name);
    CWire wire(c.wire);
    RmfCurve *profile = c_profile(c.profile);
    RmfWireSweepOptions o;
    rmf_wire_sweep_options_init(&o);
    o.corner = c.corner;
    o.corner_radius = c.corner_radius;
    o.initial_normal = RmfVec3{c.f2.X(), c.f2.Y(), c.f2.Z()};
    o.closure_symmetry = c.closure;
    o.tolerance = 1e-5;
    RmfShape *shape = nullptr;
    if (rmf_wire_sweep(wire.edges.data(), wire.edges.size(), profile, nullptr, 0, &o, &shape) != RMF_OK) {
        std::printf("  rmf_wire_sweep: %s  FAILED\n", rmf_last_error());
        failures++;
        rmf_curve_free(profile);
        return;
    }
    const char *tmp = std::getenv("TMPDIR");
    const std::string path = std::string(tmp ? tmp : "/tmp") + "/occ_wire_" + std::to_string((long)getpid()) + ".step";
    require(rmf_shape_write_step(shape, path.c_str()) == RMF_OK, "rmf_shape_write_step");
    const TopoDS_Shape read = wire_sweep::read_step(path);
    std::remove(path.c_str());
    const Measure ours = wire_sweep::measure(read);
    // The same solid handed over in OpenCascade's own B-rep text: built as it is, no file.
    const Measure handed = wire_sweep::measure(wire_sweep::read_brep_text(occ_text(shape)));
    require(handed.valid && handed.solids == 1, "OpenCascade builds one valid Solid from the B-rep text");
    check_binary(occ_binary(shape), handed, "OpenCascade builds one valid Solid from the binary B-rep");
    check(std::fabs(handed.volume - ours.volume) <= 1e-9 * ours.volume,
          "volume from the B-rep text against the STEP solid's, relative",
          std::fabs(handed.volume - ours.volume) / ours.volume, 1e-9);
    // And built from the library's B-rep model: the same solid, no text.
    const TopoDS_Shape solid = from_model(shape);
    const Measure built = wire_sweep::measure(solid);
    require(built.valid && built.solids == 1, "BRep_Builder builds one valid Solid from the B-rep model");
    check(std::fabs(built.volume - handed.volume) <= 1e-12 * handed.volume,
          "volume from the B-rep model against the text's, relative",
          std::fabs(built.volume - handed.volume) / handed.volume, 1e-12);
    check_boolean(solid, built.volume);
    RmfSweepReport report;
    rmf_shape_report(shape, &report);
    require(ours.valid && ours.solids == 1, "OpenCascade reads one valid Solid (BRepCheck_Analyzer)");
    if (c.exact > 0)
        check(std::fabs(ours.volume - c.exact) <= 1e-9 * c.exact,
              "volume (BRepGProp, adaptive) against the closed form, relative",
              std::fabs(ours.volume - c.exact) / c.exact, 1e-9);
    std::vector<size_t> straight;
    for (size_t e = 0; e < c.wire.size(); ++e) {
        bool curve = false;
        for (size_t k : c.curve_edges) curve = curve || k == e;
        if (!curve) straight.push_back(e);
    }
    if (c.cos_limit > 0) {
        check(c_face_cosine(shape, straight) <= c.cos_limit, "max |cos| between parameter lines, lines and arcs",
              c_face_cosine(shape, straight), c.cos_limit);
        if (!c.curve_edges.empty())
            check(c_face_cosine(shape, c.curve_edges) <= 1e-6, "max |cos| between parameter lines, NURBS edges",
                  c_face_cosine(shape, c.curve_edges), 1e-6);
    }
    if (c.corner_radius > 0 || c.corner == RMF_CORNER_MITER)
        check(report.corner_turn <= 1e-12, "frame's turn about the tangent across the corners, rad",
              report.corner_turn, 1e-12);
    if (c.closure) check(report.seam_gap <= 1e-12, "seam gap where the wire closes", report.seam_gap, 1e-12);
    // OpenCascade's sweep of the same wire, from the same start frame.
    BRepAdaptor_Curve start(wire_sweep::occ_edge(c.wire[0]));
    gp_Pnt origin;
    gp_Vec d1;
    start.D1(start.FirstParameter(), origin, d1);
    const gp_Dir tangent(d1);
    const double exact = c.exact > 0 ? c.exact : ours.volume;
    std::printf("  | %-28s | %-26s | valid | solids | volume error%s | max cos | poles |\n", "wire", "sweep",
                c.exact > 0 ? "" : " (vs rmfsurf)");
    wire_sweep::print_row(c.name, "rmfsurf (STEP)", ours, exact, false);
    wire_sweep::print_row(c.name, "rmfsurf (B-rep text)", handed, exact, false);
    wire_sweep::print_row(c.name, "rmfsurf (B-rep model)", built, exact, false);
    const bool round = c.corner == RMF_CORNER_ROUND;
    for (int frenet = 0; frenet <= 1; ++frenet) {
        const Measure occ = wire_sweep::in_child(
            [&] { return wire_sweep::pipe_shell(c.wire, c.profile, origin, tangent, c.f2, frenet == 1, round); }, 1,
            60);
        wire_sweep::print_row(c.name, frenet ? "MakePipeShell Frenet" : "MakePipeShell corr. Frenet", occ, exact,
                              false);
    }
    rmf_shape_free(shape);
    rmf_curve_free(profile);
}

/// A ring (radii 2 and 1) swept round a closed square loop with round corners: a solid with
/// a cavity, two closed shells of one solid from the model and from the text, the volume
/// π (R² − r²) L.
static void cavity() {
    std::printf("ring round a closed loop (a solid with a cavity)\n");
    const gp_Pnt p[5] = {gp_Pnt(0, 0, 0), gp_Pnt(20, 0, 0), gp_Pnt(20, 20, 0), gp_Pnt(0, 20, 0), gp_Pnt(0, 0, 0)};
    std::vector<Edge> loop;
    for (int i = 0; i < 4; ++i) loop.push_back(line(p[i], p[i + 1]));
    CWire wire(loop);
    RmfCurve *outer = nullptr, *hole = nullptr;
    require(rmf_curve_circle(RmfVec3{0, 0, 0}, RmfVec3{1, 0, 0}, RmfVec3{0, 1, 0}, 2, &outer) == RMF_OK &&
                rmf_curve_circle(RmfVec3{0, 0, 0}, RmfVec3{1, 0, 0}, RmfVec3{0, 1, 0}, 1, &hole) == RMF_OK,
            "rmf_curve_circle");
    RmfWireSweepOptions o;
    rmf_wire_sweep_options_init(&o);
    o.initial_normal = RmfVec3{0, 0, 1};
    RmfShape *shape = nullptr;
    const RmfCurve *holes[1] = {hole};
    require(rmf_wire_sweep(wire.edges.data(), wire.edges.size(), outer, holes, 1, &o, &shape) == RMF_OK,
            "rmf_wire_sweep");
    if (shape) {
        const TopoDS_Shape solid = from_model(shape);
        int shells = 0;
        for (TopExp_Explorer e(solid, TopAbs_SHELL); e.More(); e.Next()) ++shells;
        const Measure built = wire_sweep::measure(solid);
        const Measure handed = wire_sweep::measure(wire_sweep::read_brep_text(occ_text(shape)));
        require(built.valid && built.solids == 1 && shells == 2, "from the model: one valid Solid of two shells");
        require(handed.valid && handed.solids == 1, "from the text: one valid Solid");
        check_binary(occ_binary(shape), handed, "from the binary B-rep: one valid Solid");
        const double r = 3, exact = PI * 3 * (80 - 4 * (2 * r - r * PI / 2));
        check(std::fabs(built.volume - exact) <= 1e-9 * exact, "volume against pi (R^2 - r^2) L, relative",
              std::fabs(built.volume - exact) / exact, 1e-9);
        check_boolean(solid, built.volume);
    }
    rmf_shape_free(shape);
    rmf_curve_free(outer);
    rmf_curve_free(hole);
}

/// The square-to-round hopper (square 200 × 200, circle of radius 60 at height 150 offset by
/// 20, thickness 2): its solid from the B-rep text and from the model, the same valid solid.
static void hopper() {
    std::printf("square-to-round hopper (sheet metal)\n");
    const RmfVec3 corners[4] = {{-100, -100, 0}, {100, -100, 0}, {100, 100, 0}, {-100, 100, 0}};
    RmfCurve *square = nullptr, *circle = nullptr;
    RmfSheetPart *part = nullptr;
    require(rmf_curve_polygon(corners, 4, &square) == RMF_OK, "rmf_curve_polygon");
    require(rmf_curve_circle(RmfVec3{20, 0, 150}, RmfVec3{1, 0, 0}, RmfVec3{0, 1, 0}, 60, &circle) == RMF_OK,
            "rmf_curve_circle");
    RmfSheetOptions o;
    rmf_sheet_options_init(&o);
    o.thickness = 2;
    require(rmf_sheet_part_transition(square, circle, &o, &part) == RMF_OK, "rmf_sheet_part_transition");
    size_t length = 0;
    require(rmf_sheet_part_export(part, RMF_SHEET_FORMAT_OCC_BREP, nullptr, 0, &length) == RMF_OK,
            "rmf_sheet_part_export (size)");
    std::string text(length + 1, '\0');
    require(rmf_sheet_part_export(part, RMF_SHEET_FORMAT_OCC_BREP, text.data(), text.size(), &length) ==
                RMF_OK,
            "rmf_sheet_part_export");
    text.resize(length);
    const Measure handed = wire_sweep::measure(wire_sweep::read_brep_text(text));
    RmfBrep *brep = nullptr;
    require(rmf_sheet_part_brep(part, &brep) == RMF_OK, "rmf_sheet_part_brep");
    const TopoDS_Shape solid = rmfsurf::occ::build(brep);
    size_t size = 0;
    require(rmf_brep_occ_binary(brep, RMF_OCC_READER_BINTOOLS, nullptr, 0, &size) == RMF_OK,
            "rmf_brep_occ_binary (size)");
    std::string bytes(size, '\0');
    require(rmf_brep_occ_binary(brep, RMF_OCC_READER_BINTOOLS, reinterpret_cast<uint8_t *>(bytes.data()), size,
                                &size) == RMF_OK,
            "rmf_brep_occ_binary");
    rmf_brep_free(brep);
    const Measure built = wire_sweep::measure(solid);
    require(handed.valid && handed.solids == 1, "the hopper from the B-rep text: one valid Solid");
    check_binary(bytes, handed, "the hopper from the binary B-rep: one valid Solid");
    require(built.valid && built.solids == 1, "the hopper from the B-rep model: one valid Solid");
    check(std::fabs(built.volume - handed.volume) <= 1e-12 * handed.volume,
          "the hopper's volume from the model against the text's, relative",
          std::fabs(built.volume - handed.volume) / handed.volume, 1e-12);
    std::printf("  %d B-spline faces, volume %.9f\n", built.bspline_faces, built.volume);
    check_boolean(solid, built.volume);
    rmf_sheet_part_free(part);
    rmf_curve_free(square);
    rmf_curve_free(circle);
}

int main() {
    const double s = 0.70710678118654752440;
    const Profile circle{true, 1.0};
    // The pipe route: line, tangent quarter arc of radius 5, line.
    std::vector<Edge> route = {line(gp_Pnt(0, 0, 0), gp_Pnt(10, 0, 0)),
                               arc(gp_Pnt(10, 0, 0), gp_Pnt(10 + 5 * s, 5 - 5 * s, 0), gp_Pnt(15, 5, 0)),
                               line(gp_Pnt(15, 5, 0), gp_Pnt(15, 15, 0))};
    run(Case{"line-arc-line, circle r = 1", route, circle, RMF_CORNER_ROUND, 0, gp_Dir(0, 0, 1),
             PI * (20 + 2.5 * PI), 1e-12, {}, 0});
    // And on into the NURBS edge (G1 with the last line).
    std::vector<Edge> with_nurbs = route;
    Edge nurbs;
    nurbs.kind = Kind::Nurbs;
    nurbs.degree = 3;
    nurbs.poles = {gp_Pnt(15, 15, 0), gp_Pnt(15, 20, 0), gp_Pnt(20, 25, 5), gp_Pnt(25, 25, 5)};
    nurbs.knots = {0, 0, 0, 0, 1, 1, 1, 1};
    with_nurbs.push_back(nurbs);
    run(Case{"line-arc-line-NURBS, r = 1", with_nurbs, circle, RMF_CORNER_ROUND, 0, gp_Dir(0, 0, 1), 0, 1e-12, {3},
             0});
    // A 3-D polyline with three right angles, legs of 6, square profile of half side 0.5.
    std::vector<Edge> stairs = {line(gp_Pnt(0, 0, 0), gp_Pnt(6, 0, 0)), line(gp_Pnt(6, 0, 0), gp_Pnt(6, 6, 0)),
                                line(gp_Pnt(6, 6, 0), gp_Pnt(6, 6, 6)), line(gp_Pnt(6, 6, 6), gp_Pnt(0, 6, 6))};
    const Profile square{false, 0.5};
    run(Case{"polyline, round corners r = 1", stairs, square, RMF_CORNER_ROUND, 1.0, gp_Dir(0, 0, 1),
             24 - 3 * (2 - PI / 2), 1e-12, {}, 0});
    run(Case{"polyline, miter corners", stairs, square, RMF_CORNER_MITER, 0, gp_Dir(0, 0, 1), 24, 0, {}, 0});
    // A rounded rectangle (closed), square profile.
    auto quarter = [&](double cx, double cy, double a) {
        auto p = [&](double t) { return gp_Pnt(cx + std::cos(t), cy + std::sin(t), 0); };
        return arc(p(a), p(a + PI / 4), p(a + PI / 2));
    };
    std::vector<Edge> rounded = {line(gp_Pnt(0, -1, 0), gp_Pnt(4, -1, 0)), quarter(4, 0, -PI / 2),
                                 line(gp_Pnt(5, 0, 0), gp_Pnt(5, 2, 0)),   quarter(4, 2, 0),
                                 line(gp_Pnt(4, 3, 0), gp_Pnt(0, 3, 0)),   quarter(0, 2, PI / 2),
                                 line(gp_Pnt(-1, 2, 0), gp_Pnt(-1, 0, 0)), quarter(0, 0, PI)};
    // A closed cubic NURBS: eight uniform spans of a periodic B-spline through a bent loop.
    Edge loop;
    loop.kind = Kind::Nurbs;
    loop.degree = 3;
    std::vector<gp_Pnt> c(8);
    for (int i = 0; i < 8; ++i) {
        const double a = 2 * PI * i / 8;
        c[i] = gp_Pnt(4 * std::cos(a), 3 * std::sin(a), 1.5 * std::sin(2 * a));
    }
    auto mix = [](const gp_Pnt &a, double wa, const gp_Pnt &b, double wb, const gp_Pnt &e, double we) {
        return gp_Pnt((a.XYZ() * wa + b.XYZ() * wb + e.XYZ() * we) / (wa + wb + we));
    };
    for (int i = 0; i < 8; ++i) {
        const gp_Pnt &a = c[i], &b = c[(i + 1) % 8], &d = c[(i + 2) % 8];
        loop.poles.push_back(mix(a, 1, b, 4, d, 1));
        loop.poles.push_back(mix(b, 2, d, 1, a, 0));
        loop.poles.push_back(mix(b, 1, d, 2, a, 0));
    }
    loop.poles.push_back(loop.poles[0]);
    loop.knots = {0, 0, 0, 0};
    for (int i = 1; i < 8; ++i) loop.knots.insert(loop.knots.end(), {double(i), double(i), double(i)});
    loop.knots.insert(loop.knots.end(), {8, 8, 8, 8});
    run(Case{"closed NURBS, square 0.3", {loop}, Profile{false, 0.3}, RMF_CORNER_ROUND, 0, gp_Dir(0, 0, 1), 0, 0, {},
             4});
    run(Case{"rounded rectangle (closed)", rounded, Profile{false, 0.2}, RMF_CORNER_ROUND, 0, gp_Dir(0, 0, 1),
             0.16 * (12 + 2 * PI), 1e-12, {}, 1});
    cavity();
    hopper();
    return failures == 0 ? (std::printf("occ_wire: all checks passed\n"), 0)
                         : (std::printf("occ_wire: %d check(s) failed\n", failures), 1);
}
