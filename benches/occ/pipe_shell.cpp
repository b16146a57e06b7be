// OpenCascade's sweep, for the side-by-side benchmark (benches/compare.rs): reads a spine
// (rational Bézier segments, the Bézier views of an rmfsurf curve) and a profile placed at
// the spine's start, sweeps it with BRepOffsetAPI_MakePipeShell in corrected-Frenet mode
// (the engine of FreeCAD's Part Sweep), and writes the time of the fastest of `repeats`
// builds and every face of the result as a NURBS surface, so that the benchmark measures it
// with the same code as rmfsurf's own surfaces.
//
// Input (stdin, whitespace separated):
//   segments <n>, then per segment: <degree> and degree + 1 lines "x y z w"
//   profile line <x0 y0 z0> <x1 y1 z1>  |  profile circle <cx cy cz> <nx ny nz> <r>
//   repeats <n>
// Output (stdout):
//   time_ms <t>
//   faces <k>, then per face: <degree_u degree_v poles_u poles_v>, <knot_count_u> knots,
//   <knot_count_v> knots (each knot repeated by its multiplicity), poles_u * poles_v lines
//   "x y z w" (index i * poles_v + j)
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepOffsetAPI_MakePipeShell.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <GC_MakeSegment.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_BezierCurve.hxx>
#include <Geom_Circle.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>
#include <gp_Circ.hxx>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <stdexcept>
#include <string>

static void expect(std::istream &in, const std::string &word) {
    std::string got;
    if (!(in >> got) || got != word) throw std::runtime_error("expected '" + word + "', got '" + got + "'");
}

static gp_Pnt read_point(std::istream &in) {
    double x, y, z;
    in >> x >> y >> z;
    return gp_Pnt(x, y, z);
}

/// The spine as a wire of one rational Bézier edge per segment (G1 at the joints).
static TopoDS_Wire read_spine(std::istream &in) {
    expect(in, "segments");
    int n = 0;
    in >> n;
    BRepBuilderAPI_MakeWire wire;
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

static TopoDS_Shape sweep(const TopoDS_Wire &spine, const TopoDS_Wire &profile) {
    BRepOffsetAPI_MakePipeShell pipe(spine);
    pipe.SetMode(Standard_False); // corrected Frenet
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

int main() {
    try {
        TopoDS_Wire spine = read_spine(std::cin), profile = read_profile(std::cin);
        expect(std::cin, "repeats");
        int repeats = 1;
        std::cin >> repeats;
        double best = 1e300;
        TopoDS_Shape shape;
        for (int r = 0; r < repeats; r++) {
            const auto start = std::chrono::steady_clock::now();
            shape = sweep(spine, profile);
            const std::chrono::duration<double, std::milli> took = std::chrono::steady_clock::now() - start;
            if (took.count() < best) best = took.count();
        }
        std::printf("time_ms %.6f\n", best);
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
