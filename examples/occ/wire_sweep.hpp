// Wire sweeps in OpenCascade, shared by examples/occ/occ_wire.cpp (rmfsurf's solids read by
// OpenCascade from STEP and from its own B-rep text, beside OpenCascade's own sweep of the
// same wires) and the benchmark
// driver benches/occ/wire_pipe_shell.cpp:
//
//  - wires of lines, arcs (three points) and NURBS edges, and the profile (a circle or a
//    square) placed at the wire's start in its normal plane;
//  - BRepOffsetAPI_MakePipeShell (FreeCAD's Part Sweep) in corrected-Frenet or Frenet mode,
//    with right or round corners, made solid, in a child process with a time limit (it can
//    fail, or hang on corners and long helices);
//  - one measure for every shape: BRepCheck_Analyzer validity, the number of solids, the
//    volume by OpenCascade's adaptive integration (BRepGProp with a tolerance), the largest
//    |cos| between parameter lines of every face (sampled), and the poles of its B-spline
//    faces (analytic faces counted apart).
#ifndef RMFSURF_OCC_WIRE_SWEEP_HPP
#define RMFSURF_OCC_WIRE_SWEEP_HPP

#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_TransitionMode.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRepOffsetAPI_MakePipeShell.hxx>
#include <BRepTools.hxx>
#include <BinTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GC_MakeArcOfCircle.hxx>
#include <GProp_GProps.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>
#include <gp_Circ.hxx>

#include <sstream>

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace wire_sweep {

enum class Kind { Line, Arc, Nurbs };

/// One edge of a wire: a line (p[0], p[1]), an arc (p[0] through p[1] to p[2]) or a NURBS
/// (flat knots).
struct Edge {
    Kind kind = Kind::Line;
    gp_Pnt p[3];
    int degree = 0;
    std::vector<gp_Pnt> poles;
    std::vector<double> weights, knots;
};

/// The profile: a circle of radius `size`, or a square of half side `size`.
struct Profile {
    bool circle;
    double size;
};

/// What a shape is, measured the same way for every sweep.
struct Measure {
    bool built = false;
    std::string failure;   // why it was not built
    bool valid = false;
    int solids = 0;
    double volume = 0;     // adaptive integration
    double max_cos = 0;    // over all faces
    int bspline_poles = 0, bspline_faces = 0, analytic_faces = 0;
    double seconds = 0;    // the fastest build (benchmark only)
};

inline TopoDS_Edge occ_edge(const Edge &e) {
    switch (e.kind) {
    case Kind::Line:
        return BRepBuilderAPI_MakeEdge(e.p[0], e.p[1]).Edge();
    case Kind::Arc:
        return BRepBuilderAPI_MakeEdge(GC_MakeArcOfCircle(e.p[0], e.p[1], e.p[2]).Value()).Edge();
    case Kind::Nurbs: {
        const int n = (int)e.poles.size();
        TColgp_Array1OfPnt poles(1, n);
        TColStd_Array1OfReal weights(1, n);
        for (int i = 0; i < n; ++i) {
            poles(i + 1) = e.poles[i];
            weights(i + 1) = e.weights.empty() ? 1.0 : e.weights[i];
        }
        std::vector<double> distinct;
        std::vector<int> mult;
        for (double k : e.knots) {
            if (!distinct.empty() && k == distinct.back())
                mult.back()++;
            else
                distinct.push_back(k), mult.push_back(1);
        }
        TColStd_Array1OfReal knots(1, (int)distinct.size());
        TColStd_Array1OfInteger mults(1, (int)distinct.size());
        for (size_t i = 0; i < distinct.size(); ++i) knots((int)i + 1) = distinct[i], mults((int)i + 1) = mult[i];
        Handle(Geom_BSplineCurve) c = new Geom_BSplineCurve(poles, weights, knots, mults, e.degree);
        return BRepBuilderAPI_MakeEdge(c).Edge();
    }
    }
    return TopoDS_Edge();
}

inline TopoDS_Wire occ_wire(const std::vector<Edge> &edges) {
    BRepBuilderAPI_MakeWire wire;
    for (const Edge &e : edges) wire.Add(occ_edge(e));
    return wire.Wire();
}

/// The profile in the plane through `origin` normal to `tangent`, x along `f2`.
inline TopoDS_Wire occ_profile(const Profile &p, gp_Pnt origin, gp_Dir tangent, gp_Dir f2) {
    if (p.circle) {
        gp_Circ circle(gp_Ax2(origin, tangent, f2), p.size);
        return BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(circle).Edge()).Wire();
    }
    const gp_Vec x(f2), y = gp_Vec(tangent).Crossed(x);
    BRepBuilderAPI_MakePolygon square;
    const double a = p.size, c[5][2] = {{a, a}, {-a, a}, {-a, -a}, {a, -a}, {a, a}};
    for (const auto &k : c) square.Add(origin.Translated(x * k[0] + y * k[1]));
    return square.Wire();
}

/// The largest |cos| between the parameter lines of a face, sampled on 12 × 12 points of
/// its parameter box (inside it).
inline double face_cosine(const TopoDS_Face &face) {
    BRepAdaptor_Surface s(face);
    double u0, u1, v0, v1, worst = 0;
    BRepTools::UVBounds(face, u0, u1, v0, v1);
    for (int i = 0; i <= 12; ++i)
        for (int j = 0; j <= 12; ++j) {
            gp_Pnt p;
            gp_Vec du, dv;
            s.D1(u0 + (u1 - u0) * (0.02 + 0.96 * i / 12), v0 + (v1 - v0) * (0.02 + 0.96 * j / 12), p, du, dv);
            const double m = du.Magnitude() * dv.Magnitude();
            if (m > 0) worst = std::max(worst, std::fabs(du.Dot(dv)) / m);
        }
    return worst;
}

inline Measure measure(const TopoDS_Shape &shape) {
    Measure m;
    m.built = true;
    m.valid = BRepCheck_Analyzer(shape).IsValid();
    for (TopExp_Explorer e(shape, TopAbs_SOLID); e.More(); e.Next()) m.solids++;
    GProp_GProps props;
    BRepGProp::VolumeProperties(shape, props, 1e-12, Standard_True);
    m.volume = props.Mass();
    for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) {
        const TopoDS_Face face = TopoDS::Face(e.Current());
        m.max_cos = std::max(m.max_cos, face_cosine(face));
        Handle(Geom_BSplineSurface) b = Handle(Geom_BSplineSurface)::DownCast(BRep_Tool::Surface(face));
        if (b.IsNull()) {
            m.analytic_faces++;
        } else {
            m.bspline_faces++;
            m.bspline_poles += b->NbUPoles() * b->NbVPoles();
        }
    }
    return m;
}

/// A STEP file read by OpenCascade's reader.
inline TopoDS_Shape read_step(const std::string &path) {
    STEPControl_Reader reader;
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) return TopoDS_Shape();
    reader.TransferRoots();
    return reader.OneShape();
}

/// The shape OpenCascade builds from its own B-rep text (what rmf_shape_occ_brep hands
/// over): no file, no sewing.
inline TopoDS_Shape read_brep_text(const std::string &text) {
    std::istringstream stream(text);
    TopoDS_Shape shape;
    BRep_Builder builder;
    BRepTools::Read(shape, stream, builder);
    return shape;
}

/// The shape OpenCascade builds from its binary B-rep (what rmf_shape_occ_binary and
/// rmf_brep_occ_binary hand over for RMF_OCC_READER_BINTOOLS): no file, no parsing, no sewing.
inline TopoDS_Shape read_brep_binary(const std::string &bytes) {
    std::istringstream stream(bytes, std::ios::in | std::ios::binary);
    TopoDS_Shape shape;
    BinTools::Read(shape, stream);
    return shape;
}

/// The sweep of `profile` along `edges` by BRepOffsetAPI_MakePipeShell, made solid.
inline TopoDS_Shape pipe_shell(const std::vector<Edge> &edges, const Profile &profile, gp_Pnt origin, gp_Dir tangent,
                               gp_Dir f2, bool frenet, bool round) {
    BRepOffsetAPI_MakePipeShell pipe(occ_wire(edges));
    pipe.SetMode(frenet ? Standard_True : Standard_False); // False: corrected Frenet
    pipe.SetTransitionMode(round ? BRepBuilderAPI_RoundCorner : BRepBuilderAPI_RightCorner);
    pipe.Add(occ_profile(profile, origin, tangent, f2));
    pipe.Build();
    if (!pipe.IsDone()) throw Standard_Failure("MakePipeShell: not done");
    if (!pipe.MakeSolid()) throw Standard_Failure("MakePipeShell: MakeSolid failed");
    return pipe.Shape();
}

/// Runs `build` (which returns a shape) `repeats` times in a child process, at most
/// `limit` seconds in all, and measures the last shape there; the child reports through a
/// pipe. A failure, a crash or the time limit gives an unbuilt Measure with the reason.
template <class Build> Measure in_child(Build build, int repeats, double limit) {
    int fd[2];
    if (pipe(fd) != 0) return Measure{false, "pipe() failed"};
    std::fflush(stdout);
    const pid_t child = fork();
    if (child == 0) {
        close(fd[0]);
        Measure m;
        try {
            TopoDS_Shape shape;
            double best = 1e300;
            for (int r = 0; r < repeats; ++r) {
                const auto start = std::chrono::steady_clock::now();
                shape = build();
                const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
                best = std::min(best, took.count());
            }
            m = measure(shape);
            m.seconds = best;
        } catch (const Standard_Failure &e) {
            m.failure = std::string("OpenCascade: ") + (e.GetMessageString() ? e.GetMessageString() : "failure");
        } catch (...) {
            m.failure = "an exception";
        }
        char text[512];
        const int n = std::snprintf(text, sizeof text, "%d %d %d %.17g %.17g %d %d %d %.17g|%s", (int)m.built,
                                    (int)m.valid, m.solids, m.volume, m.max_cos, m.bspline_poles, m.bspline_faces,
                                    m.analytic_faces, m.seconds, m.failure.c_str());
        if (write(fd[1], text, (size_t)std::min(n, (int)sizeof text - 1)) < 0) _exit(2);
        _exit(0);
    }
    close(fd[1]);
    Measure m;
    std::string text;
    struct pollfd p = {fd[0], POLLIN, 0};
    const auto start = std::chrono::steady_clock::now();
    for (;;) {
        const double left = limit - std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (left <= 0) {
            kill(child, SIGKILL);
            m.failure = "no result within " + std::to_string((int)limit) + " s (hangs)";
            break;
        }
        if (poll(&p, 1, (int)(left * 1000) + 1) > 0) {
            char buffer[512];
            const ssize_t n = read(fd[0], buffer, sizeof buffer);
            if (n <= 0) break;
            text.append(buffer, (size_t)n);
        }
    }
    close(fd[0]);
    int status = 0;
    waitpid(child, &status, 0);
    if (!text.empty()) {
        int built = 0, valid = 0;
        char failure[400] = "";
        std::sscanf(text.c_str(), "%d %d %d %lg %lg %d %d %d %lg|%399[^\n]", &built, &valid, &m.solids, &m.volume,
                    &m.max_cos, &m.bspline_poles, &m.bspline_faces, &m.analytic_faces, &m.seconds, failure);
        m.built = built, m.valid = valid, m.failure = failure;
    } else if (m.failure.empty()) {
        m.failure = "crashed (status " + std::to_string(status) + ")";
    }
    return m;
}

/// One row of the comparison table.
inline void print_row(const char *wire, const char *method, const Measure &m, double exact, bool timed) {
    if (!m.built) {
        std::printf("| %-28s | %-26s | failed: %s |\n", wire, method, m.failure.c_str());
        return;
    }
    std::printf("| %-28s | %-26s | %-5s | %d | %.1e | %.1e | %d (%d B-spline, %d analytic faces)", wire, method,
                m.valid ? "yes" : "NO", m.solids, std::fabs(m.volume - exact) / exact, m.max_cos, m.bspline_poles,
                m.bspline_faces, m.analytic_faces);
    if (timed) std::printf(" | %.3f ms", m.seconds * 1e3);
    std::printf(" |\n");
}

}  // namespace wire_sweep

#endif
