/*
 * Sweeps along RRMF quintics with their exact rational RMF (Farouki, Giannelli & Sestini),
 * checked independently with the suite's NURBS evaluator, OpenMesh and VTK
 * (surface_checks.hpp):
 *
 *  - a straight-line profile swept with an RMF gives a developable surface (Mäurer &
 *    Jüttler, Proposition 2): analytic K = 0, and the discrete curvatures of OpenMesh and
 *    VTK vanish too;
 *  - a circle profile gives a tube whose parameter lines are lines of curvature, hence
 *    orthogonal (Proposition 3): |cos ∠(s_u, s_v)| ≤ 1e-9 — the frame is exact, not an
 *    approximation — while its Gaussian curvature (positive outside, negative inside) is far
 *    from zero, which the discrete measures must resolve.
 *
 * Spines: the RRMF quintic spline through the helix data of Example 3, and the fair
 * Example 1 interpolant (η = 4.325).
 */
#include "surface_checks.hpp"

extern "C" {
#include "rmf_check.h"
}

#include <cmath>

using rmf_checks::check_surface;
using rmf_checks::print_report;
using rmf_checks::SurfaceReport;

/* A straight segment of the normal plane: x ↦ f2 offset 0.15, y ↦ f3 from −0.25 to 0.25. */
static RmfCurve *line_profile() {
    const RmfVec3 poles[2] = {{0.15, -0.25, 0}, {0.15, 0.25, 0}};
    const double knots[4] = {0, 0, 1, 1};
    RmfCurve *c = nullptr;
    CHECK_STATUS(rmf_nurbs_curve_create(1, poles, nullptr, 2, knots, 4, &c), RMF_OK, "");
    return c;
}

/* A full circle of radius r about the spine: rational quadratic, four quarter arcs. */
static RmfCurve *circle_profile(double r) {
    const double ring[9][3] = {{1, 0, 1}, {1, 1, 0}, {0, 1, 1}, {-1, 1, 0}, {-1, 0, 1},
                               {-1, -1, 0}, {0, -1, 1}, {1, -1, 0}, {1, 0, 1}};
    const double knots[12] = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
    RmfVec3 poles[9];
    double weights[9];
    for (int i = 0; i < 9; ++i) {
        poles[i] = vec3(r * ring[i][0], r * ring[i][1], 0);
        weights[i] = ring[i][2] == 1 ? 1.0 : std::sqrt(0.5);
    }
    RmfCurve *c = nullptr;
    CHECK_STATUS(rmf_nurbs_curve_create(2, poles, weights, 9, knots, 12, &c), RMF_OK, "");
    return c;
}

/* Sweeps both profiles along the spine, checks and prints. */
static void check_sweeps(const char *name, const RmfCurve *spine, const RmfFrames *frames, int steps_v) {
    RmfCurve *line = line_profile(), *circle = circle_profile(0.3);
    RmfSurface *strip = nullptr, *tube = nullptr;
    CHECK_STATUS(rmf_sweep_surface(spine, frames, line, &strip), RMF_OK, "");
    CHECK_STATUS(rmf_sweep_surface(spine, frames, circle, &tube), RMF_OK, "");
    if (strip && tube) {
        RmfNurbsSurface view;
        CHECK_STATUS(rmf_surface_nurbs(strip, &view), RMF_OK, "");
        std::printf("%s: line sweep of degree (%u, %u), %zu x %zu poles; circle sweep of degree", name,
                    view.degree_u, view.degree_v, view.pole_count_u, view.pole_count_v);
        const SurfaceReport s = check_surface(view, 20, steps_v);
        CHECK_STATUS(rmf_surface_nurbs(tube, &view), RMF_OK, "");
        std::printf(" (%u, %u)\n", view.degree_u, view.degree_v);
        const SurfaceReport t = check_surface(view, 8, steps_v);
        print_report("  line profile (developable)", s);
        print_report("  circle profile (tube)", t);
        std::printf("  tube: max|K_OpenMesh - K|s^2 %.3e, max|K_VTK - K|s^2 %.3e\n", t.max_dev_openmesh,
                    t.max_dev_vtk);
        CHECK(s.interior_vertices > 500 && t.interior_vertices > 500, "enough interior vertices");
        // The RMF is exact: parameter lines are lines of curvature on both sweeps.
        CHECK(t.max_cos <= 1e-9, "tube: parameter lines orthogonal to 1e-9");
        CHECK(s.max_cos <= 1e-9, "strip: parameter lines orthogonal to 1e-9");
        // The line sweep is developable ...
        CHECK(s.max_k_analytic <= 1e-9, "strip: analytic K = 0");
        // ... and the discrete measures agree: they resolve the tube's curvature, and on the
        // strip see less than a thousandth of it.
        CHECK(t.max_k_analytic > 10.0, "tube: K is far from zero");
        CHECK(t.max_dev_openmesh < 0.05 * t.max_k_analytic, "tube: OpenMesh resolves K");
        CHECK(t.max_dev_vtk < 0.05 * t.max_k_analytic, "tube: VTK resolves K");
        CHECK(s.max_k_openmesh < 1e-3 * t.max_k_analytic, "strip: OpenMesh sees no curvature");
        CHECK(s.max_k_vtk < 1e-3 * t.max_k_analytic, "strip: VTK sees no curvature");
    }
    rmf_surface_free(strip);
    rmf_surface_free(tube);
    rmf_curve_free(line);
    rmf_curve_free(circle);
}

static void helix_spline() {
    RmfVec3 points[10], tangents[10];
    for (int k = 0; k < 10; ++k) {
        const double t = k * M_PI / 2;
        points[k] = vec3(std::sin(t), std::cos(t), t);
        tangents[k] = vec3(std::cos(t), -std::sin(t), 1);
    }
    RmfCurve *spine = nullptr;
    RmfFrames *frames = nullptr;
    CHECK_STATUS(rmf_rrmf_spline_hermite(points, tangents, 10, vec3(-1, 0, 0), RMF_RRMF_MEASURE_SCALED_ENERGY_RMF, 64,
                                         &spine, &frames),
                 RMF_OK, "");
    if (spine && frames) check_sweeps("Example 3 helix spline", spine, frames, 6);
    rmf_frames_free(frames);
    rmf_curve_free(spine);
}

static void example_1_quintic() {
    const RmfVec3 p0 = {0, 0, 0}, t0 = {1, 0, 1}, p1 = {1, 1, 1}, t1 = {0, 1, 1};
    RmfRrmfQuintic s[4];
    size_t n = 0;
    CHECK_STATUS(rmf_rrmf_quintic_solutions(p0, t0, p1, t1, 4.325, s, 4, &n), RMF_OK, "");
    if (n == 0) return;
    RmfCurve *spine = nullptr;
    RmfFrames *frames = nullptr;
    CHECK_STATUS(rmf_rrmf_quintic_curve(p0, t0, p1, t1, &s[0], vec3(0, 0, 1), &spine, &frames), RMF_OK, "");
    if (spine && frames) check_sweeps("Example 1 quintic, eta = 4.325", spine, frames, 40);
    rmf_frames_free(frames);
    rmf_curve_free(spine);
}

int main() {
    helix_spline();
    example_1_quintic();
    return rmf_check_exit_code("geometry_rrmf_quintic");
}
