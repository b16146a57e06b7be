// rmfsurf in an OpenCascade kernel: exact rational surfaces from the C API become
// Geom_BSplineSurface objects, and OpenCascade checks them.
//
// For each surface the library makes (a developable strip swept with the PH cubic rational
// RMF, a pipe and a strip with exact rational RMFs by Moebius maps and RRMF quintics, a
// cone spline strip and its development) the program
//   1. builds a Geom_BSplineSurface from rmf_surface_nurbs (poles, weights, distinct knots
//      with multiplicities, both degrees) and a face from it (BRepBuilderAPI_MakeFace),
//   2. checks the face with BRepCheck_Analyzer,
//   3. compares OpenCascade's points and first derivatives with rmf_surface_eval on a
//      41 x 41 grid,
//   4. measures the Gaussian curvature with GeomLProp_SLProps: |K|·size² ~ 0 on the
//      developables, clearly non-zero on the pipe (the measure can fail).
// It prints one line per figure and exits 1 if any figure misses its limit.
//
/* Build (Debian: libocct-modeling-algorithms-dev), after cargo build --release:
     g++ -std=c++17 -Iinclude -isystem /usr/include/opencascade examples/occ/occ_kernel.cpp \
         -Ltarget/release -lrmfsurf -Wl,-rpath,$PWD/target/release \
         -lTKTopAlgo -lTKGeomAlgo -lTKBRep -lTKGeomBase -lTKG3d -lTKG2d -lTKMath -lTKernel \
         -o occ_kernel                                                                      */

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <GeomLProp_SLProps.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Precision.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "rmfsurf.h"

namespace {

const double pi = std::acos(-1.0);
int failures = 0;

void figure(const std::string &name, double value, double limit, bool below = true) {
    const bool ok = below ? value <= limit : value >= limit;
    std::printf("  %-62s %10.3e  (%s %.0e)%s\n", name.c_str(), value, below ? "<=" : ">=", limit,
                ok ? "" : "  FAILED");
    if (!ok) ++failures;
}

// Aborts with the library's message when a call fails: the example's inputs are valid.
void require(RmfStatus status, const char *what) {
    if (status != RMF_OK) {
        std::fprintf(stderr, "%s failed: %s: %s\n", what, rmf_status_name(status), rmf_last_error());
        std::exit(2);
    }
}

// Owned library handles.
struct CurveFree { void operator()(RmfCurve *c) const { rmf_curve_free(c); } };
struct FramesFree { void operator()(RmfFrames *f) const { rmf_frames_free(f); } };
struct SurfaceFree { void operator()(RmfSurface *s) const { rmf_surface_free(s); } };
struct SplineFree { void operator()(RmfConeSpline *s) const { rmf_cone_spline_free(s); } };
using Curve = std::unique_ptr<RmfCurve, CurveFree>;
using Frames = std::unique_ptr<RmfFrames, FramesFree>;
using Surface = std::unique_ptr<RmfSurface, SurfaceFree>;
using Spline = std::unique_ptr<RmfConeSpline, SplineFree>;

// A clamped flat knot vector as OpenCascade's distinct knots and multiplicities.
void knots_and_multiplicities(const double *knots, size_t count, TColStd_Array1OfReal *&distinct,
                              TColStd_Array1OfInteger *&multiplicities) {
    std::vector<double> k;
    std::vector<int> m;
    for (size_t i = 0; i < count; ++i) {
        if (!k.empty() && knots[i] == k.back()) {
            ++m.back();
        } else {
            k.push_back(knots[i]);
            m.push_back(1);
        }
    }
    distinct = new TColStd_Array1OfReal(1, static_cast<int>(k.size()));
    multiplicities = new TColStd_Array1OfInteger(1, static_cast<int>(k.size()));
    for (size_t i = 0; i < k.size(); ++i) {
        distinct->SetValue(static_cast<int>(i) + 1, k[i]);
        multiplicities->SetValue(static_cast<int>(i) + 1, m[i]);
    }
}

// The library's NURBS view as an OpenCascade surface (pole (i, j) at i * pole_count_v + j,
// i along u: OpenCascade's (row, column) = (u index, v index), both from 1).
Handle(Geom_BSplineSurface) to_occ(const RmfSurface *surface) {
    RmfNurbsSurface view;
    require(rmf_surface_nurbs(surface, &view), "rmf_surface_nurbs");
    const int nu = static_cast<int>(view.pole_count_u), nv = static_cast<int>(view.pole_count_v);
    TColgp_Array2OfPnt poles(1, nu, 1, nv);
    TColStd_Array2OfReal weights(1, nu, 1, nv);
    for (int i = 0; i < nu; ++i) {
        for (int j = 0; j < nv; ++j) {
            const RmfVec3 &p = view.poles[i * nv + j];
            poles.SetValue(i + 1, j + 1, gp_Pnt(p.x, p.y, p.z));
            weights.SetValue(i + 1, j + 1, view.weights[i * nv + j]);
        }
    }
    TColStd_Array1OfReal *ku, *kv;
    TColStd_Array1OfInteger *mu, *mv;
    knots_and_multiplicities(view.knots_u, view.knot_count_u, ku, mu);
    knots_and_multiplicities(view.knots_v, view.knot_count_v, kv, mv);
    Handle(Geom_BSplineSurface) result = new Geom_BSplineSurface(
        poles, weights, *ku, *kv, *mu, *mv, static_cast<int>(view.degree_u), static_cast<int>(view.degree_v));
    delete ku, delete kv, delete mu, delete mv;
    return result;
}

gp_Vec vec(const RmfVec3 &v) { return gp_Vec(v.x, v.y, v.z); }

// The checks of the header comment for one surface.
void check(const char *name, const RmfSurface *surface, bool developable) {
    std::printf("%s\n", name);
    Handle(Geom_BSplineSurface) occ = to_occ(surface);
    BRepBuilderAPI_MakeFace maker(occ, Precision::Confusion());
    figure("face made and valid (BRepCheck_Analyzer): 1 = yes",
           maker.IsDone() && BRepCheck_Analyzer(maker.Face()).IsValid() ? 1.0 : 0.0, 1.0, false);
    double u0, u1, v0, v1;
    require(rmf_surface_domain(surface, &u0, &u1, &v0, &v1), "rmf_surface_domain");
    const int n = 41;
    double point_error = 0, derivative_error = 0, k_max = 0;
    gp_Pnt lo(1e300, 1e300, 1e300), hi(-1e300, -1e300, -1e300);
    std::vector<std::pair<double, double>> inner;
    for (int a = 0; a < n; ++a) {
        for (int b = 0; b < n; ++b) {
            const double u = u0 + (u1 - u0) * a / (n - 1), v = v0 + (v1 - v0) * b / (n - 1);
            RmfVec3 p, du, dv;
            require(rmf_surface_eval(surface, u, v, &p, &du, &dv), "rmf_surface_eval");
            gp_Pnt q;
            gp_Vec qu, qv;
            occ->D1(u, v, q, qu, qv);
            point_error = std::max(point_error, q.Distance(gp_Pnt(p.x, p.y, p.z)));
            derivative_error = std::max({derivative_error, (qu - vec(du)).Magnitude() / vec(du).Magnitude(),
                                         (qv - vec(dv)).Magnitude() / vec(dv).Magnitude()});
            lo.SetCoord(std::min(lo.X(), p.x), std::min(lo.Y(), p.y), std::min(lo.Z(), p.z));
            hi.SetCoord(std::max(hi.X(), p.x), std::max(hi.Y(), p.y), std::max(hi.Z(), p.z));
            if (a > 0 && a < n - 1 && b > 0 && b < n - 1) inner.emplace_back(u, v);
        }
    }
    figure("|OCC point - rmf_surface_eval|", point_error, 1e-9);
    figure("|OCC derivative - rmf_surface_eval| / |derivative|", derivative_error, 1e-9);
    const double size = lo.Distance(hi);
    for (const auto &[u, v] : inner) {
        GeomLProp_SLProps props(occ, u, v, 2, Precision::Confusion());
        if (props.IsCurvatureDefined()) k_max = std::max(k_max, std::fabs(props.GaussianCurvature()));
    }
    if (developable) {
        figure("GeomLProp_SLProps max |K|·size² (developable)", k_max * size * size, 1e-8);
    } else {
        figure("GeomLProp_SLProps max |K|·size² (not developable: large)", k_max * size * size, 1.0, false);
    }
}

void helix(double t, void *, RmfVec3 *point, RmfVec3 *tangent) {
    *point = RmfVec3{std::cos(t), std::sin(t), 0.4 * t};
    *tangent = RmfVec3{-std::sin(t), std::cos(t), 0.4};
}

void twisted_cubic(double t, void *, RmfVec3 *point, RmfVec3 *tangent) {
    *point = RmfVec3{t, t * t, t * t * t};
    *tangent = RmfVec3{1, 2 * t, 3 * t * t};
}

Curve nurbs_curve(uint32_t degree, const std::vector<RmfVec3> &poles, const std::vector<double> &weights,
                  const std::vector<double> &knots) {
    RmfCurve *c = nullptr;
    require(rmf_nurbs_curve_create(degree, poles.data(), weights.empty() ? nullptr : weights.data(), poles.size(),
                                   knots.data(), knots.size(), &c),
            "rmf_nurbs_curve_create");
    return Curve(c);
}

Surface swept(const RmfCurve *spine, const RmfFrames *frames, const RmfCurve *profile) {
    RmfSurface *s = nullptr;
    require(rmf_sweep_surface(spine, frames, profile, &s), "rmf_sweep_surface");
    return Surface(s);
}

}  // namespace

int main() {
    std::printf("rmfsurf %s with OpenCascade: Geom_BSplineSurface from rmf_surface_nurbs\n", rmf_version());
    const RmfVec3 up{0, 0, 1};
    Curve line = nurbs_curve(1, {{-0.2, 0, 0}, {0.2, 0, 0}}, {}, {0, 0, 1, 1});
    const double s = std::sqrt(0.5);
    Curve circle = nurbs_curve(2, {{0.2, 0, 0}, {0.2, 0.2, 0}, {0, 0.2, 0}, {-0.2, 0.2, 0}, {-0.2, 0, 0},
                                   {-0.2, -0.2, 0}, {0, -0.2, 0}, {0.2, -0.2, 0}, {0.2, 0, 0}},
                               {1, s, 1, s, 1, s, 1, s, 1}, {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4});

    // PH cubic spline within 1e-6 of a helix, its rational RMF, a line swept: developable.
    RmfCurve *ph_raw = nullptr;
    RmfFrames *rmf_raw = nullptr;
    require(rmf_ph_spline_approximate(nullptr, helix, nullptr, 0, 2 * pi, 1e-6, &ph_raw, nullptr),
            "rmf_ph_spline_approximate");
    Curve ph(ph_raw);
    require(rmf_ph_rational_rmf(ph.get(), up, &rmf_raw), "rmf_ph_rational_rmf");
    Frames rmf(rmf_raw);
    check("PH cubic spline, rational RMF, line profile", swept(ph.get(), rmf.get(), line.get()).get(), true);

    // Exact rational RMFs: Moebius (pipe) and RRMF quintics (strip) through helix samples.
    std::vector<RmfVec3> points, tangents;
    for (int k = 0; k <= 8; ++k) {
        RmfVec3 p, t;
        helix(2 * pi * k / 8, nullptr, &p, &t);
        points.push_back(p);
        tangents.push_back(t);
    }
    RmfCurve *mobius_raw = nullptr, *rrmf_raw = nullptr;
    RmfFrames *mobius_frames_raw = nullptr, *rrmf_frames_raw = nullptr;
    require(rmf_mobius_rrmf_hermite(points.data(), tangents.data(), points.size(), up, &mobius_raw,
                                    &mobius_frames_raw),
            "rmf_mobius_rrmf_hermite");
    Curve mobius(mobius_raw);
    Frames mobius_frames(mobius_frames_raw);
    check("Moebius exact rational RMF, circle profile (a pipe)",
          swept(mobius.get(), mobius_frames.get(), circle.get()).get(), false);
    require(rmf_rrmf_spline_hermite(points.data(), tangents.data(), points.size(), up,
                                    RMF_RRMF_MEASURE_SCALED_ENERGY_RMF, 64, &rrmf_raw, &rrmf_frames_raw),
            "rmf_rrmf_spline_hermite");
    Curve rrmf(rrmf_raw);
    Frames rrmf_frames(rrmf_frames_raw);
    check("RRMF quintics, exact rational RMF, line profile", swept(rrmf.get(), rrmf_frames.get(), line.get()).get(),
          true);

    // A cone spline within 1e-4 of the tangent surface of (t, t², t³), and its development.
    RmfConeSpline *spline_raw = nullptr, *flat_raw = nullptr;
    RmfCurve *cubic_raw = nullptr;
    require(rmf_callback_curve_create(twisted_cubic, nullptr, 0.2, 1.2, &cubic_raw), "rmf_callback_curve_create");
    Curve cubic(cubic_raw);
    RmfConeApproximationOptions options;
    require(rmf_cone_approximation_options_init(&options), "rmf_cone_approximation_options_init");
    options.tolerance = 1e-4;
    require(rmf_cone_spline_approximate_with_options(cubic.get(), 0.5, 6.0, &options, &spline_raw, nullptr),
            "rmf_cone_spline_approximate_with_options");
    Spline spline(spline_raw);
    require(rmf_cone_spline_develop(spline.get(), &flat_raw), "rmf_cone_spline_develop");
    Spline flat(flat_raw);
    RmfSurface *strip = nullptr, *pattern = nullptr;
    require(rmf_cone_spline_surface(spline.get(), -0.3, 0.3, &strip), "rmf_cone_spline_surface");
    Surface strip_owned(strip);
    check("cone spline strip", strip, true);
    require(rmf_cone_spline_surface(flat.get(), -0.3, 0.3, &pattern), "rmf_cone_spline_surface");
    Surface pattern_owned(pattern);
    check("its development", pattern, true);

    std::printf(failures ? "OCC CHECKS FAILED: %d\n" : "OCC CHECKS OK\n", failures);
    return failures ? 1 : 0;
}
