// OpenCascade's sweep, for the side-by-side benchmark (benches/compare.rs): reads a spine
// and a profile placed at the spine's start, sweeps it with BRepOffsetAPI_MakePipeShell
// (the engine of FreeCAD's Part Sweep) in corrected-Frenet or Frenet mode, and writes the
// time of each of `repeats` builds, whether BRepCheck_Analyzer finds the shape valid,
// and every face of the result as a NURBS surface, so that the benchmark measures it with the
// same code as rmfsurf's own surfaces. A second use, `check`, reads one NURBS surface (an
// rmfsurf result), makes a face of it and reports the same validity check.
//
// Input (stdin, whitespace separated):
//   spine, one of
//     segments <n>, then per segment: <degree> and degree + 1 lines "x y z w"
//       (one rational Bézier edge per segment)
//     nurbs <degree> <pole_count> <knot_count>, the knots (each repeated by its
//       multiplicity), pole_count lines "x y z w" (one B-spline edge: the user's NURBS data)
//     wire <n>, then per edge: line <p0> <p1> | arc <p0> <through> <p1>
//       (a wire of analytic edges: Geom_TrimmedCurve of a line or circle, as CAD users draw)
//   profile line <x0 y0 z0> <x1 y1 z1>  |  profile circle <cx cy cz> <nx ny nz> <r>
//   mode corrected_frenet | frenet
//   tolerance <tol3d>   (BRepOffsetAPI_MakePipeShell::SetTolerance; 0 keeps the default 1e-4)
//   repeats <n>
// or
//   check <degree_u degree_v poles_u poles_v>, <knot_count_u> knots, <knot_count_v> knots,
//   poles_u * poles_v lines "x y z w" (index i * poles_v + j)
// Output (stdout):
//   times_ms <repeats> <t1> … (milliseconds per build)
//   valid <0|1>
//   faces <k>, then per face: <degree_u degree_v poles_u poles_v>, <knot_count_u> knots,
//   <knot_count_v> knots (each knot repeated by its multiplicity), poles_u * poles_v lines
//   "x y z w" (index i * poles_v + j)
// or, for check: valid <0|1>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepOffsetAPI_MakePipeShell.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <GC_MakeArcOfCircle.hxx>
#include <GC_MakeSegment.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_BezierCurve.hxx>
#include <Geom_Circle.hxx>
#include <Precision.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>
#include <gp_Circ.hxx>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

static void expect(std::istream &in, const std::string &word) {
    std::string got;
    if (!(in >> got) || got != word) throw std::runtime_error("expected '" + word + "', got '" + got + "'");
}

static gp_Pnt read_point(std::istream &in) {
    double x, y, z;
    in >> x >> y >> z;
    return gp_Pnt(x, y, z);
}

/// Flat knots (each repeated by its multiplicity) as OpenCascade's distinct knots and
/// multiplicities.
static void distinct_knots(const std::vector<double> &flat, Handle(TColStd_HArray1OfReal) & knots,
                           Handle(TColStd_HArray1OfInteger) & multiplicities) {
    std::vector<double> values;
    std::vector<int> counts;
    for (double k : flat) {
        if (!values.empty() && k == values.back())
            counts.back()++;
        else {
            values.push_back(k);
            counts.push_back(1);
        }
    }
    knots = new TColStd_HArray1OfReal(1, (int)values.size());
    multiplicities = new TColStd_HArray1OfInteger(1, (int)values.size());
    for (size_t i = 0; i < values.size(); i++) {
        knots->SetValue((int)i + 1, values[i]);
        multiplicities->SetValue((int)i + 1, counts[i]);
    }
}

static std::vector<double> read_numbers(std::istream &in, int n) {
    std::vector<double> v(n);
    for (int i = 0; i < n; i++) in >> v[i];
    return v;
}

/// One B-spline edge from NURBS data (after the word "nurbs").
static TopoDS_Edge read_nurbs_edge(std::istream &in) {
    int degree = 0, pole_count = 0, knot_count = 0;
    in >> degree >> pole_count >> knot_count;
    std::vector<double> flat = read_numbers(in, knot_count);
    TColgp_Array1OfPnt poles(1, pole_count);
    TColStd_Array1OfReal weights(1, pole_count);
    for (int i = 1; i <= pole_count; i++) {
        poles(i) = read_point(in);
        in >> weights(i);
    }
    if (!in) throw std::runtime_error("bad NURBS spine");
    Handle(TColStd_HArray1OfReal) knots;
    Handle(TColStd_HArray1OfInteger) multiplicities;
    distinct_knots(flat, knots, multiplicities);
    Handle(Geom_BSplineCurve) curve =
        new Geom_BSplineCurve(poles, weights, knots->Array1(), multiplicities->Array1(), degree);
    return BRepBuilderAPI_MakeEdge(curve).Edge();
}

/// The spine: one rational Bézier edge per segment, or one B-spline edge.
static TopoDS_Wire read_spine(std::istream &in) {
    std::string kind;
    in >> kind;
    BRepBuilderAPI_MakeWire wire;
    if (kind == "nurbs") {
        wire.Add(read_nurbs_edge(in));
    } else if (kind == "wire") {
        int n = 0;
        in >> n;
        for (int e = 0; e < n; e++) {
            std::string edge;
            in >> edge;
            const gp_Pnt a = read_point(in);
            const gp_Pnt b = read_point(in);
            if (edge == "line") {
                wire.Add(BRepBuilderAPI_MakeEdge(GC_MakeSegment(a, b).Value()).Edge());
            } else if (edge == "arc") {
                const gp_Pnt c = read_point(in);
                wire.Add(BRepBuilderAPI_MakeEdge(GC_MakeArcOfCircle(a, b, c).Value()).Edge());
            } else {
                throw std::runtime_error("unknown edge " + edge);
            }
        }
    } else if (kind == "segments") {
        int n = 0;
        in >> n;
        for (int s = 0; s < n; s++) {
            int degree = 0;
            in >> degree;
            TColgp_Array1OfPnt poles(1, degree + 1);
            TColStd_Array1OfReal weights(1, degree + 1);
            for (int i = 1; i <= degree + 1; i++) {
                poles(i) = read_point(in);
                in >> weights(i);
            }
            Handle(Geom_BezierCurve) bezier = new Geom_BezierCurve(poles, weights);
            wire.Add(BRepBuilderAPI_MakeEdge(bezier).Edge());
        }
    } else {
        throw std::runtime_error("unknown spine " + kind);
    }
    if (!in || !wire.IsDone()) throw std::runtime_error("bad spine");
    return wire.Wire();
}

static TopoDS_Wire read_profile(std::istream &in) {
    expect(in, "profile");
    std::string kind;
    in >> kind;
    if (kind == "line") {
        gp_Pnt a = read_point(in), b = read_point(in);
        return BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(GC_MakeSegment(a, b).Value()).Edge()).Wire();
    }
    if (kind == "circle") {
        gp_Pnt c = read_point(in), n = read_point(in);
        double r = 0;
        in >> r;
        gp_Circ circle(gp_Ax2(c, gp_Dir(n.X(), n.Y(), n.Z())), r);
        return BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(circle).Edge()).Wire();
    }
    throw std::runtime_error("unknown profile " + kind);
}

// Not inlined: a profiler (valgrind --tool=callgrind --toggle-collect=sweep*) can count it alone.
__attribute__((noinline)) static TopoDS_Shape sweep(const TopoDS_Wire &spine, const TopoDS_Wire &profile, bool frenet, double tolerance) {
    BRepOffsetAPI_MakePipeShell pipe(spine);
    pipe.SetMode(frenet ? Standard_True : Standard_False); // false: corrected Frenet
    if (tolerance > 0) pipe.SetTolerance(tolerance);
    pipe.Add(profile);
    pipe.Build();
    if (!pipe.IsDone()) throw std::runtime_error("MakePipeShell failed");
    return pipe.Shape();
}

static void write_face(const TopoDS_Face &face) {
    TopoDS_Shape nurbs = BRepBuilderAPI_NurbsConvert(face).Shape();
    Handle(Geom_BSplineSurface) s =
        Handle(Geom_BSplineSurface)::DownCast(BRep_Tool::Surface(TopoDS::Face(nurbs)));
    if (s.IsNull()) throw std::runtime_error("face is not a B-spline surface");
    // A closed profile gives a periodic surface: cut to the face's parameter box, it is
    // written with clamped knots like rmfsurf's.
    s = Handle(Geom_BSplineSurface)::DownCast(s->Copy());
    if (s->IsUPeriodic()) s->SetUNotPeriodic();
    if (s->IsVPeriodic()) s->SetVNotPeriodic();
    double u1, u2, v1, v2;
    BRepTools::UVBounds(TopoDS::Face(nurbs), u1, u2, v1, v2);
    s->Segment(u1, u2, v1, v2);
    const int nu = s->NbUPoles(), nv = s->NbVPoles();
    std::printf("%d %d %d %d\n", s->UDegree(), s->VDegree(), nu, nv);
    for (int dir = 0; dir < 2; dir++) {
        const int count = dir == 0 ? s->NbUKnots() : s->NbVKnots();
        int total = 0;
        for (int k = 1; k <= count; k++) total += dir == 0 ? s->UMultiplicity(k) : s->VMultiplicity(k);
        std::printf("%d", total);
        for (int k = 1; k <= count; k++) {
            const int m = dir == 0 ? s->UMultiplicity(k) : s->VMultiplicity(k);
            const double value = dir == 0 ? s->UKnot(k) : s->VKnot(k);
            for (int r = 0; r < m; r++) std::printf(" %.17g", value);
        }
        std::printf("\n");
    }
    for (int i = 1; i <= nu; i++)
        for (int j = 1; j <= nv; j++) {
            const gp_Pnt p = s->Pole(i, j);
            std::printf("%.17g %.17g %.17g %.17g\n", p.X(), p.Y(), p.Z(), s->Weight(i, j));
        }
}

/// `check`: a face on one NURBS surface, checked like the sweeps.
static void check_surface(std::istream &in) {
    int du = 0, dv = 0, nu = 0, nv = 0, count = 0;
    in >> du >> dv >> nu >> nv >> count;
    std::vector<double> flat_u = read_numbers(in, count);
    in >> count;
    std::vector<double> flat_v = read_numbers(in, count);
    TColgp_Array2OfPnt poles(1, nu, 1, nv);
    TColStd_Array2OfReal weights(1, nu, 1, nv);
    for (int i = 1; i <= nu; i++)
        for (int j = 1; j <= nv; j++) {
            poles(i, j) = read_point(in);
            in >> weights(i, j);
        }
    if (!in) throw std::runtime_error("bad surface");
    Handle(TColStd_HArray1OfReal) ku, kv;
    Handle(TColStd_HArray1OfInteger) mu, mv;
    distinct_knots(flat_u, ku, mu);
    distinct_knots(flat_v, kv, mv);
    Handle(Geom_BSplineSurface) surface = new Geom_BSplineSurface(
        poles, weights, ku->Array1(), kv->Array1(), mu->Array1(), mv->Array1(), du, dv);
    TopoDS_Face face = BRepBuilderAPI_MakeFace(surface, Precision::Confusion()).Face();
    std::printf("valid %d\n", BRepCheck_Analyzer(face).IsValid() ? 1 : 0);
}

int main() {
    try {
        if (std::cin.peek() == 'c') {
            expect(std::cin, "check");
            check_surface(std::cin);
            return 0;
        }
        TopoDS_Wire spine = read_spine(std::cin), profile = read_profile(std::cin);
        expect(std::cin, "mode");
        std::string mode;
        std::cin >> mode;
        if (mode != "frenet" && mode != "corrected_frenet") throw std::runtime_error("unknown mode " + mode);
        expect(std::cin, "tolerance");
        double tolerance = 0;
        std::cin >> tolerance;
        expect(std::cin, "repeats");
        int repeats = 1;
        std::cin >> repeats;
        std::vector<double> times;
        TopoDS_Shape shape;
        for (int r = 0; r < repeats; r++) {
            const auto start = std::chrono::steady_clock::now();
            shape = sweep(spine, profile, mode == "frenet", tolerance);
            const std::chrono::duration<double, std::milli> took = std::chrono::steady_clock::now() - start;
            times.push_back(took.count());
        }
        std::printf("times_ms %d", (int)times.size());
        for (double t : times) std::printf(" %.6f", t);
        std::printf("\n");
        std::printf("valid %d\n", BRepCheck_Analyzer(shape).IsValid() ? 1 : 0);
        int faces = 0;
        for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) faces++;
        std::printf("faces %d\n", faces);
        for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) write_face(TopoDS::Face(e.Current()));
        return 0;
    } catch (const std::exception &e) {
        std::fprintf(stderr, "pipe_shell: %s\n", e.what());
        return 1;
    } catch (const Standard_Failure &e) {
        std::fprintf(stderr, "pipe_shell: OpenCascade: %s\n", e.GetMessageString());
        return 1;
    }
}
