/*
 * The independent checks of surface_checks.hpp, proven able to fail: a cylinder given as
 * NURBS input must come out developable with orthogonal parameter lines, a hyperbolic
 * paraboloid must not — and the discrete curvatures of OpenMesh and VTK must agree with the
 * analytic one there.
 */
// These tests call the deprecated wrappers on purpose (they keep working): no warning.
#define RMF_DEPRECATED(note)
#include "surface_checks.hpp"

extern "C" {
#include "rmf_check.h"
}

using rmf_checks::check_surface;
using rmf_checks::print_report;
using rmf_checks::SurfaceReport;

/* Cylinder of radius 1 around z, height 2: degree (2, 1), u around the axis, v along it. */
static RmfSurface *cylinder() {
    const double ring[9][3] = {{1, 0, 1}, {1, 1, 0}, {0, 1, 1}, {-1, 1, 0}, {-1, 0, 1},
                               {-1, -1, 0}, {0, -1, 1}, {1, -1, 0}, {1, 0, 1}};
    const double knots_u[12] = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
    const double knots_v[4] = {0, 0, 2, 2};
    RmfVec3 poles[18];
    double weights[18];
    for (int i = 0; i < 9; ++i)
        for (int j = 0; j < 2; ++j) {
            poles[i * 2 + j] = RmfVec3{ring[i][0], ring[i][1], 2.0 * j};
            weights[i * 2 + j] = ring[i][2] == 1 ? 1.0 : std::sqrt(0.5);
        }
    RmfSurface *s = nullptr;
    CHECK_STATUS(rmf_nurbs_surface_create(2, 1, poles, weights, 9, 2, knots_u, 12, knots_v, 4, &s), RMF_OK, "");
    return s;
}

/* z = x y over [−1, 1]², a bilinear patch: K = −1 / (1 + x² + y²)² ≠ 0 everywhere. */
static RmfSurface *hyperbolic_paraboloid() {
    const RmfVec3 poles[4] = {{-1, -1, 1}, {-1, 1, -1}, {1, -1, -1}, {1, 1, 1}};
    const double knots[4] = {0, 0, 1, 1};
    RmfSurface *s = nullptr;
    CHECK_STATUS(rmf_nurbs_surface_create(1, 1, poles, nullptr, 2, 2, knots, 4, knots, 4, &s), RMF_OK, "");
    return s;
}

int main() {
    RmfSurface *cyl = cylinder(), *hyp = hyperbolic_paraboloid();
    if (!cyl || !hyp) return rmf_check_exit_code("geometry_foundation");
    RmfNurbsSurface view;

    CHECK_STATUS(rmf_surface_nurbs(cyl, &view), RMF_OK, "");
    const SurfaceReport c = check_surface(view, 12, 6);
    print_report("cylinder (developable)", c);
    CHECK(c.interior_vertices > 100, "enough interior vertices");
    CHECK(c.max_cos < 1e-12, "cylinder: parameter lines are orthogonal");
    CHECK(c.max_k_analytic < 1e-10, "cylinder: analytic K = 0");
    CHECK(c.max_defect < 1e-12, "cylinder: OpenMesh angle defect = 0 (vertices on rulings)");
    CHECK(c.max_k_openmesh < 1e-9, "cylinder: OpenMesh discrete K = 0");
    CHECK(c.max_k_vtk < 1e-9, "cylinder: vtkCurvatures K = 0");

    CHECK_STATUS(rmf_surface_nurbs(hyp, &view), RMF_OK, "");
    const SurfaceReport h = check_surface(view, 40, 40);
    print_report("hyperbolic paraboloid", h);
    std::printf("%-28s max|K_OpenMesh - K|s^2 %.3e, max|K_VTK - K|s^2 %.3e, min|K|s^2 analytic %.3e\n", "",
                h.max_dev_openmesh, h.max_dev_vtk, h.min_k_analytic);
    CHECK(h.max_cos > 0.45, "hyperbolic paraboloid: parameter lines are not orthogonal (0.5 at the corners)");
    CHECK(h.max_k_analytic > 10.0, "hyperbolic paraboloid: analytic |K| s^2 = 12 at the centre");
    CHECK(h.min_k_analytic > 1.0, "hyperbolic paraboloid: K is non-zero at every interior vertex");
    CHECK(h.max_defect > 1e-4, "hyperbolic paraboloid: OpenMesh sees an angle defect");
    CHECK(h.max_dev_openmesh < 0.05 * h.max_k_analytic, "OpenMesh discrete K matches the analytic K");
    CHECK(h.max_dev_vtk < 0.05 * h.max_k_analytic, "vtkCurvatures K matches the analytic K");

    rmf_surface_free(cyl);
    rmf_surface_free(hyp);
    return rmf_check_exit_code("geometry_foundation");
}
