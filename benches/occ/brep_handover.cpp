// The handover to an OpenCascade program, end to end in C++ (part of scripts/bench): for each
// case the whole call — rmfsurf's construction, then the kernel's shape built from the
// library's B-rep model with BRep_Builder (rmf_shape_brep / rmf_sheet_part_brep and
// include/rmfsurf_occ.hpp) or from its B-rep text (rmf_shape_occ_brep, BRepTools::Read) —
// beside BRepOffsetAPI_MakePipeShell on the same wire (corrected Frenet, round corners, made
// solid). Best of 5, milliseconds; every shape checked valid (BRepCheck_Analyzer) once.
#include <BRepCheck_Analyzer.hxx>
#include <Standard_Version.hxx>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "rmfsurf.h"
#include "rmfsurf_occ.hpp"
#include "../../examples/occ/wire_sweep.hpp"

using wire_sweep::Edge;
using wire_sweep::Kind;

static double best_ms(const std::function<void()> &call, int runs = 5) {
    double best = 1e300;
    for (int r = 0; r < runs; ++r) {
        const auto start = std::chrono::steady_clock::now();
        call();
        const std::chrono::duration<double, std::milli> took = std::chrono::steady_clock::now() - start;
        best = std::min(best, took.count());
    }
    return best;
}

static void must(RmfStatus status, const char *call) {
    if (status != RMF_OK) {
        std::fprintf(stderr, "%s: %s\n", call, rmf_last_error());
        std::exit(1);
    }
}

static RmfEdge c_edge(const Edge &e) {
    RmfEdge c{};
    c.kind = e.kind == Kind::Line ? RMF_EDGE_LINE : RMF_EDGE_ARC;
    for (int i = 0; i < 3; ++i) c.points[i] = RmfVec3{e.p[i].X(), e.p[i].Y(), e.p[i].Z()};
    return c;
}

static std::string shape_text(const RmfShape *shape) {
    size_t length = 0;
    must(rmf_shape_occ_brep(shape, nullptr, 0, &length), "rmf_shape_occ_brep");
    std::string text(length + 1, '\0');
    must(rmf_shape_occ_brep(shape, text.data(), text.size(), &length), "rmf_shape_occ_brep");
    text.resize(length);
    return text;
}

static TopoDS_Shape from_model(const RmfShape *shape) {
    RmfBrep *brep = nullptr;
    must(rmf_shape_brep(shape, &brep), "rmf_shape_brep");
    TopoDS_Shape built = rmfsurf::occ::build(brep);
    rmf_brep_free(brep);
    return built;
}

static std::string shape_binary(const RmfShape *shape) {
    size_t length = 0;
    must(rmf_shape_occ_binary(shape, RMF_OCC_READER_BINTOOLS, nullptr, 0, &length), "rmf_shape_occ_binary");
    std::string bytes(length, '\0');
    must(rmf_shape_occ_binary(shape, RMF_OCC_READER_BINTOOLS, reinterpret_cast<uint8_t *>(bytes.data()),
                              bytes.size(), &length),
         "rmf_shape_occ_binary");
    return bytes;
}

static void row(const char *name, double theirs, double library, double model, double text, double binary) {
    std::printf("| %-40s | %9.2f | %8.2f | %8.2f | %8.2f | %8.2f | %6.2fx | %6.2fx | %6.2fx |\n", name, theirs,
                library, model, text, binary, theirs / (library + model), theirs / (library + text),
                theirs / (library + binary));
}

static void sweep_case(const char *name, const std::vector<Edge> &wire, double radius) {
    std::vector<RmfEdge> edges;
    for (const Edge &e : wire) edges.push_back(c_edge(e));
    RmfCurve *profile = nullptr;
    must(rmf_curve_circle(RmfVec3{0, 0, 0}, RmfVec3{1, 0, 0}, RmfVec3{0, 1, 0}, radius, &profile), "rmf_curve_circle");
    const gp_Pnt a = wire[0].p[0], b = wire[0].kind == Kind::Line ? wire[0].p[1] : wire[0].p[1];
    const gp_Dir tangent(gp_Vec(a, b));
    const gp_Dir f2 = std::fabs(tangent.Z()) < 0.9 ? gp_Dir(tangent.Crossed(gp_Dir(0, 0, 1))) : gp_Dir(1, 0, 0);
    RmfWireSweepOptions o;
    rmf_wire_sweep_options_init(&o);
    o.initial_normal = RmfVec3{f2.X(), f2.Y(), f2.Z()};
    RmfShape *shape = nullptr;
    const double library = best_ms([&] {
        rmf_shape_free(shape);
        shape = nullptr;
        must(rmf_wire_sweep(edges.data(), edges.size(), profile, nullptr, 0, &o, &shape), "rmf_wire_sweep");
    });
    // Each handover on a shape made anew (the library keeps the text it made).
    double model = 1e300, text = 1e300, binary = 1e300;
    TopoDS_Shape by_model, by_text, by_binary;
    for (int r = 0; r < 5; ++r) {
        RmfShape *fresh = nullptr;
        must(rmf_wire_sweep(edges.data(), edges.size(), profile, nullptr, 0, &o, &fresh), "rmf_wire_sweep");
        model = std::min(model, best_ms([&] { by_model = from_model(fresh); }, 1));
        text = std::min(text, best_ms([&] { by_text = wire_sweep::read_brep_text(shape_text(fresh)); }, 1));
        binary =
            std::min(binary, best_ms([&] { by_binary = wire_sweep::read_brep_binary(shape_binary(fresh)); }, 1));
        rmf_shape_free(fresh);
    }
    const wire_sweep::Profile circle{true, radius};
    TopoDS_Shape pipe;
    const double theirs =
        best_ms([&] { pipe = wire_sweep::pipe_shell(wire, circle, a, tangent, f2, false, true); });
    if (!BRepCheck_Analyzer(by_model).IsValid() || !BRepCheck_Analyzer(by_text).IsValid() ||
        !BRepCheck_Analyzer(by_binary).IsValid())
        std::printf("| %s: rmfsurf's shape INVALID\n", name);
    if (!BRepCheck_Analyzer(pipe).IsValid()) std::printf("| %s: MakePipeShell's shape invalid\n", name);
    row(name, theirs, library, model, text, binary);
    rmf_shape_free(shape);
    rmf_curve_free(profile);
}

static void hopper(double tolerance) {
    const RmfVec3 corners[4] = {{-100, -100, 0}, {100, -100, 0}, {100, 100, 0}, {-100, 100, 0}};
    RmfCurve *square = nullptr, *circle = nullptr;
    must(rmf_curve_polygon(corners, 4, &square), "rmf_curve_polygon");
    must(rmf_curve_circle(RmfVec3{20, 0, 150}, RmfVec3{1, 0, 0}, RmfVec3{0, 1, 0}, 60, &circle), "rmf_curve_circle");
    RmfSheetOptions o;
    rmf_sheet_options_init(&o);
    o.thickness = 2;
    o.tolerance = tolerance;
    RmfSheetPart *part = nullptr;
    const double library = best_ms([&] {
        rmf_sheet_part_free(part);
        part = nullptr;
        must(rmf_sheet_part_transition(square, circle, &o, &part), "rmf_sheet_part_transition");
    });
    double model = 1e300, text = 1e300;
    TopoDS_Shape by_model, by_text;
    for (int r = 0; r < 5; ++r) {
        RmfSheetPart *fresh = nullptr;
        must(rmf_sheet_part_transition(square, circle, &o, &fresh), "rmf_sheet_part_transition");
        model = std::min(model, best_ms(
                                    [&] {
                                        RmfBrep *brep = nullptr;
                                        must(rmf_sheet_part_brep(fresh, &brep), "rmf_sheet_part_brep");
                                        by_model = rmfsurf::occ::build(brep);
                                        rmf_brep_free(brep);
                                    },
                                    1));
        text = std::min(text, best_ms(
                                  [&] {
                                      size_t length = 0;
                                      must(rmf_sheet_part_export(fresh, RMF_SHEET_FORMAT_OCC_BREP, nullptr, 0,
                                                                       &length),
                                           "rmf_sheet_part_export");
                                      std::string t(length + 1, '\0');
                                      must(rmf_sheet_part_export(fresh, RMF_SHEET_FORMAT_OCC_BREP, t.data(),
                                                                       t.size(), &length),
                                           "rmf_sheet_part_export");
                                      t.resize(length);
                                      by_text = wire_sweep::read_brep_text(t);
                                  },
                                  1));
        rmf_sheet_part_free(fresh);
    }
    if (!BRepCheck_Analyzer(by_model).IsValid() || !BRepCheck_Analyzer(by_text).IsValid())
        std::printf("| hopper: rmfsurf's shape INVALID\n");
    char name[64];
    std::snprintf(name, sizeof name, "square-to-round transition, tol %g", tolerance);
    std::printf("| %-40s | %9s | %8.2f | %8.2f | %8.2f | %8s | %7s | %7s | %7s |\n", name, "—", library, model, text,
                "", "", "", "");
    rmf_sheet_part_free(part);
    rmf_curve_free(square);
    rmf_curve_free(circle);
}

int main() {
    const double s = std::sqrt(0.5);
    auto line = [](gp_Pnt a, gp_Pnt b) {
        Edge e;
        e.kind = Kind::Line;
        e.p[0] = a, e.p[1] = b;
        return e;
    };
    auto arc = [](gp_Pnt a, gp_Pnt m, gp_Pnt b) {
        Edge e;
        e.kind = Kind::Arc;
        e.p[0] = a, e.p[1] = m, e.p[2] = b;
        return e;
    };
    std::printf("| OpenCascade %s, C++: the whole call, best of 5, milliseconds\n", OCC_VERSION_COMPLETE);
    std::printf("| %-40s | %9s | %8s | %8s | %8s | %8s | %7s | %7s | %7s |\n", "case", "PipeShell", "library",
                "+ model", "+ text", "+ binary", "ratio m", "ratio t", "ratio b");
    sweep_case("pipe route (line, arc, line), circle",
               {line(gp_Pnt(0, 0, 0), gp_Pnt(10, 0, 0)),
                arc(gp_Pnt(10, 0, 0), gp_Pnt(10 + 5 * s, 5 - 5 * s, 0), gp_Pnt(15, 5, 0)),
                line(gp_Pnt(15, 5, 0), gp_Pnt(15, 15, 0))},
               1.0);
    std::vector<Edge> zigzag;
    for (int i = 0; i < 100; ++i)
        zigzag.push_back(line(gp_Pnt(10 * i, 10 * (i % 2), 0), gp_Pnt(10 * (i + 1), 10 * ((i + 1) % 2), 0)));
    sweep_case("100-edge polyline, round corners, circle", zigzag, 1.0);
    hopper(1e-3);
    hopper(1e-4);
    std::printf("| library: rmfsurf's construction; + model: the B-rep model built by BRep_Builder "
                "(rmfsurf_occ.hpp); + text: the B-rep text read by BRepTools::Read; + binary: the "
                "binary B-rep read by BinTools::Read; ratios: "
                "MakePipeShell's time over rmfsurf's whole call\n");
    return 0;
}
