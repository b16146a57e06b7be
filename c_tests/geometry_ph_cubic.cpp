/*
 * The figures of Mäurer & Jüttler §3.5 on profile surfaces over a PH cubic spline spine,
 * measured from the exported NURBS data with the suite's own evaluator, OpenMesh and VTK
 * (surface_checks.hpp), never with the library's evaluators:
 *
 *  - orthogonality of the parameter lines, max |O(u, v)| of (43): ≤ 1e-6 on the sweep with the
 *    rational RMF (the paper: 3.2e-7), ≥ 1e-2 on the Frenet sweep of the same data (0.08);
 *  - developability of the sweep of a straight line, |K|·size²: ≤ 1e-5 with the rational RMF
 *    (the paper: 5e-6), analytically and by the discrete measures; clearly non-zero with the
 *    Frenet frame.
 *
 * The Frenet frame of a G1 spline jumps at the joints, so its sweeps are checked segment by
 * segment (the same PH cubics, each made from its Hermite data).
 */
#include <cmath>
#include <vector>

#include "surface_checks.hpp"

extern "C" {
#include "rmf_check.h"
}

using rmf_checks::check_surface;
using rmf_checks::print_report;
using rmf_checks::SurfaceReport;

/* The spine data: n + 1 samples (n ≤ 16) of the conical helix
 * ((t/2 + 1) cos t, (t/2 + 1) sin t, 0.3 t), t ∈ [1, 5], whose curvature and torsion vary. */
static void spine_data(int n, RmfVec3 points[17], RmfVec3 tangents[17]) {
    for (int i = 0; i <= n; ++i) {
        const double t = 1.0 + 4.0 * i / n, r = 0.5 * t + 1.0;
        points[i] = RmfVec3{r * std::cos(t), r * std::sin(t), 0.3 * t};
        tangents[i] = RmfVec3{0.5 * std::cos(t) - r * std::sin(t), 0.5 * std::sin(t) + r * std::cos(t), 0.3};
    }
}

/* The PH cubic spline through the spine data. */
static RmfCurve *spine(int n) {
    RmfVec3 points[17], tangents[17];
    spine_data(n, points, tangents);
    RmfCurve *c = nullptr;
    CHECK_STATUS(rmf_ph_spline_hermite(points, tangents, (size_t)n + 1, &c), RMF_OK, "");
    return c;
}

/* Segment i of that spline on its own (the same PH cubic, from the same Hermite data). */
static RmfCurve *spine_segment(int n, int i) {
    RmfVec3 points[17], tangents[17];
    spine_data(n, points, tangents);
    RmfCurve *c = nullptr;
    CHECK_STATUS(rmf_ph_cubic_hermite(points[i], tangents[i], points[i + 1], tangents[i + 1], &c, nullptr), RMF_OK,
                 "");
    return c;
}

/* A profile from Bézier poles (degree = count − 1), weights optional. */
static RmfCurve *profile(const std::vector<RmfVec3> &poles, const double *weights) {
    const size_t n = poles.size();
    std::vector<double> knots(2 * n);
    for (size_t i = 0; i < n; ++i) knots[i] = 0, knots[n + i] = 1;
    RmfCurve *c = nullptr;
    CHECK_STATUS(rmf_nurbs_curve_create((uint32_t)(n - 1), poles.data(), weights, n, knots.data(), knots.size(), &c),
                 RMF_OK, "");
    return c;
}

static RmfSurface *sweep(const RmfCurve *spine, const RmfFrames *frames, const RmfCurve *profile) {
    RmfSurface *s = nullptr;
    CHECK_STATUS(rmf_sweep_surface(spine, frames, profile, &s), RMF_OK, "");
    return s;
}

/* The surface as one NURBS. */
static SurfaceReport whole(const RmfSurface *s, int steps_u, int steps_v) {
    RmfNurbsSurface view;
    CHECK_STATUS(rmf_surface_nurbs(s, &view), RMF_OK, "");
    return check_surface(view, steps_u, steps_v);
}

/* The worst figures of the Frenet sweeps of the spine's segments, each on its own: the
 * Frenet frame of a G1 spline jumps at the joints (the curvature does), so its sweep of the
 * whole spline is not even continuous. */
static SurfaceReport frenet_per_segment(int n, const RmfCurve *profile, int steps_u, int steps_v) {
    SurfaceReport worst;
    worst.min_k_analytic = 1e300;
    for (int i = 0; i < n; ++i) {
        RmfCurve *segment = spine_segment(n, i);
        RmfFrames *frenet = nullptr;
        if (!segment) continue;
        CHECK_STATUS(rmf_ph_frenet_frames(segment, &frenet), RMF_OK, "");
        RmfSurface *s = frenet ? sweep(segment, frenet, profile) : nullptr;
        if (s) {
            const SurfaceReport r = whole(s, steps_u, steps_v);
            worst.size = std::max(worst.size, r.size);
            worst.max_cos = std::max(worst.max_cos, r.max_cos);
            worst.max_k_analytic = std::max(worst.max_k_analytic, r.max_k_analytic);
            worst.min_k_analytic = std::min(worst.min_k_analytic, r.min_k_analytic);
            worst.max_defect = std::max(worst.max_defect, r.max_defect);
            worst.max_k_openmesh = std::max(worst.max_k_openmesh, r.max_k_openmesh);
            worst.max_k_vtk = std::max(worst.max_k_vtk, r.max_k_vtk);
            worst.interior_vertices += r.interior_vertices;
        }
        rmf_surface_free(s);
        rmf_frames_free(frenet);
        rmf_curve_free(segment);
    }
    return worst;
}

/* The profile surface of `profile` along the spine of n segments with its rational RMF. */
static RmfSurface *rmf_sweep(int n, const RmfCurve *profile, double *max_angle) {
    RmfCurve *x = spine(n);
    RmfFrames *rmf = nullptr;
    RmfSurface *s = nullptr;
    double errors[16];
    size_t count = 0;
    if (x) CHECK_STATUS(rmf_ph_rational_rmf(x, RmfVec3{0, 0, 1}, &rmf), RMF_OK, "");
    if (rmf) {
        CHECK_STATUS(rmf_ph_rmf_angle_error(rmf, errors, 16, &count, max_angle), RMF_OK, "");
        std::printf("spine: PH spline, %d segments through a conical helix; rational RMF vs exact RMF: max %.3e rad, "
                    "per segment:",
                    n, *max_angle);
        for (size_t i = 0; i < count; ++i) std::printf(" %.1e", errors[i]);
        std::printf("\n");
        s = sweep(x, rmf, profile);
    }
    rmf_frames_free(rmf);
    rmf_curve_free(x);
    return s;
}

int main() {
    /* A cubic profile in the normal plane (x → f2, y → f3), and a straight one. */
    RmfCurve *moulding = profile({{0.3, -0.2, 0}, {0.55, 0.05, 0}, {0.2, 0.3, 0}, {-0.25, 0.25, 0}}, nullptr);
    RmfCurve *line = profile({{-0.4, 0.1, 0}, {0.45, -0.15, 0}}, nullptr);
    if (!moulding || !line) return rmf_check_exit_code("geometry_ph_cubic");
    double angle8 = 0, angle16 = 0, angle_line = 0;
    RmfSurface *coarse = rmf_sweep(8, moulding, &angle8), *profile_rmf = rmf_sweep(16, moulding, &angle16);
    RmfSurface *ruled_rmf = rmf_sweep(16, line, &angle_line);
    if (!coarse || !profile_rmf || !ruled_rmf) return rmf_check_exit_code("geometry_ph_cubic");

    RmfNurbsSurface view;
    CHECK_STATUS(rmf_surface_nurbs(profile_rmf, &view), RMF_OK, "");
    CHECK(view.degree_u == 3 && view.degree_v == 9, "profile surface of degree (3, 9): (m, 2n + 5), n = 2");

    const SurfaceReport a8 = whole(coarse, 16, 24);
    const SurfaceReport a = whole(profile_rmf, 16, 24);
    const SurfaceReport b = frenet_per_segment(16, moulding, 16, 24);
    print_report("cubic profile, RMF, 8 segs", a8);
    print_report("cubic profile, RMF, 16 segs", a);
    print_report("cubic profile, Frenet, 16", b);
    CHECK(a.max_cos <= 1e-6, "RMF sweep: parameter lines orthogonal, max |O| <= 1e-6 (paper 3.2e-7)");
    /* O is proportional to the frame's angular-velocity error, the derivative of the O(h^5)
     * angle error: it falls like h^4. */
    CHECK(std::log2(a8.max_cos / a.max_cos) > 3.5, "max |O| falls with order about 4 in the segment length");

    CHECK(b.max_cos >= 1e-2, "Frenet sweep: max |O| >= 1e-2 (paper 0.08)");

    const SurfaceReport c = whole(ruled_rmf, 8, 48);
    const SurfaceReport d = frenet_per_segment(16, line, 8, 48);
    print_report("line profile, RMF, 16 segs", c);
    print_report("line profile, Frenet, 16", d);
    std::printf("%-28s Frenet ruled sweeps: min |K|s^2 analytic %.3e at interior vertices\n", "", d.min_k_analytic);
    CHECK(c.max_k_analytic <= 1e-5, "RMF ruled sweep developable: analytic |K| size^2 <= 1e-5 (paper 5e-6)");
    CHECK(c.max_k_openmesh <= 1e-5, "RMF ruled sweep developable: OpenMesh angle defect |K| size^2 <= 1e-5");
    CHECK(c.max_k_vtk <= 1e-5, "RMF ruled sweep developable: vtkCurvatures |K| size^2 <= 1e-5");
    CHECK(d.max_k_analytic > 0.05 && d.min_k_analytic > 1e-4,
          "Frenet ruled sweep: K clearly non-zero (5000 times the developability bound), nowhere zero");
    CHECK(d.max_k_openmesh > 0.05 && d.max_k_vtk > 0.05, "Frenet ruled sweep: the discrete measures see K too");

    rmf_surface_free(coarse);
    rmf_surface_free(profile_rmf);
    rmf_surface_free(ruled_rmf);
    rmf_curve_free(moulding);
    rmf_curve_free(line);
    return rmf_check_exit_code("geometry_ph_cubic");
}
