/*
 * The faces of wire sweeps, checked independently from their NURBS views with the suite's
 * own evaluator, OpenMesh and VTK (surface_checks.hpp), never with the library's evaluators:
 *
 *  - along lines, exact cylinders: the Gaussian curvature K is 0 analytically and by the
 *    discrete measures (OpenMesh angle defect, vtkCurvatures);
 *  - along arcs, exact tori: K from the NURBS derivatives equals the torus's
 *    cos φ / (r (R + r cos φ)) at every sample, and OpenMesh and VTK see the same K;
 *  - parameter lines orthogonal (max |cos| of Mäurer & Jüttler (43)): ≤ 1e-12 on lines and
 *    arcs, ≤ 1e-6 on the faces along a NURBS edge (the PH cubic spline's rational RMF).
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

static RmfCurve *circle(double r) {
    const double s = 0.70710678118654752440;
    const RmfVec3 p[9] = {{r, 0, 0},   {r, r, 0},   {0, r, 0},  {-r, r, 0}, {-r, 0, 0},
                          {-r, -r, 0}, {0, -r, 0}, {r, -r, 0}, {r, 0, 0}};
    const double w[9] = {1, s, 1, s, 1, s, 1, s, 1}, k[12] = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
    RmfCurve *c = nullptr;
    CHECK_STATUS(rmf_nurbs_curve_create(2, p, w, 9, k, 12, &c), RMF_OK, "");
    return c;
}

int main() {
    const double s = 0.70710678118654752440;
    const RmfVec3 nurbs_poles[4] = {{15, 15, 0}, {15, 20, 0}, {20, 25, 5}, {25, 25, 5}};
    const double nurbs_knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
    RmfCurve *nurbs = nullptr, *profile = circle(1);
    CHECK_STATUS(rmf_nurbs_curve_create(3, nurbs_poles, nullptr, 4, nurbs_knots, 8, &nurbs), RMF_OK, "");
    RmfEdge edges[4] = {};
    edges[0].kind = RMF_EDGE_LINE, edges[0].points[0] = {0, 0, 0}, edges[0].points[1] = {10, 0, 0};
    edges[1].kind = RMF_EDGE_ARC, edges[1].points[0] = {10, 0, 0};
    edges[1].points[1] = {10 + 5 * s, 5 - 5 * s, 0}, edges[1].points[2] = {15, 5, 0};
    edges[2].kind = RMF_EDGE_LINE, edges[2].points[0] = {15, 5, 0}, edges[2].points[1] = {15, 15, 0};
    edges[3].kind = RMF_EDGE_CURVE, edges[3].curve = nurbs;
    RmfWireSweepOptions options;
    rmf_wire_sweep_options_init(&options);
    options.tolerance = 1e-5;
    RmfShape *shape = nullptr;
    CHECK_STATUS(rmf_wire_sweep(edges, 4, profile, nullptr, 0, &options, &shape), RMF_OK, "");
    if (!shape) return rmf_check_exit_code("geometry_wire");
    double cylinder_k = 0, cylinder_discrete = 0, torus_dev = 0, torus_discrete = 0, straight_cos = 0, nurbs_cos = 0;
    size_t torus_samples = 0;
    for (size_t f = 0; f < rmf_shape_face_count(shape); ++f) {
        RmfShapeFace face;
        RmfNurbsSurface view;
        CHECK_STATUS(rmf_shape_face(shape, f, &face), RMF_OK, "");
        if (face.kind != RMF_FACE_SWEPT) continue;
        CHECK_STATUS(rmf_surface_nurbs(face.surface, &view), RMF_OK, "");
        const SurfaceReport r = check_surface(view, 8, 16);
        if (face.spine_edge == 3) {
            nurbs_cos = std::max(nurbs_cos, r.max_cos);
            continue;
        }
        straight_cos = std::max(straight_cos, r.max_cos);
        if (face.spine_edge != 1) {
            cylinder_k = std::max(cylinder_k, r.max_k_analytic);
            cylinder_discrete = std::max(cylinder_discrete, std::max(r.max_k_openmesh, r.max_k_vtk));
            continue;
        }
        // The torus about (10, 5, 0), axis z, R = 5, r = 1: K = cos φ / (r (R + r cos φ)) with
        // cos φ the point's offset from the spine circle, outwards, over r.
        for (int i = 0; i <= 16; ++i)
            for (int j = 0; j <= 16; ++j) {
                RmfVec3 d[3][3];
                const double u = view.knots_u[0] + (view.knots_u[view.knot_count_u - 1] - view.knots_u[0]) * i / 16;
                const double v = view.knots_v[0] + (view.knots_v[view.knot_count_v - 1] - view.knots_v[0]) * j / 16;
                ne_surface_derivatives(&view, u, v, d);
                const double rho = std::hypot(d[0][0].x - 10, d[0][0].y - 5), cos_phi = rho - 5;
                const double k = cos_phi / (1 * (5 + cos_phi));
                torus_dev = std::max(torus_dev, std::fabs(ne_gaussian_curvature(d) - k));
                torus_samples++;
            }
        torus_discrete = std::max(torus_discrete, std::max(r.max_dev_openmesh, r.max_dev_vtk));
        print_report("torus face (arc edge)", r);
    }
    std::printf("line faces: max |K| s^2 analytic %.1e, OpenMesh/VTK %.1e; arc faces: |K - torus K| %.1e over %zu "
                "samples, OpenMesh/VTK vs analytic %.1e; max |cos|: lines and arcs %.1e, NURBS edge %.1e\n",
                cylinder_k, cylinder_discrete, torus_dev, torus_samples, torus_discrete, straight_cos, nurbs_cos);
    CHECK(cylinder_k <= 1e-12, "cylinders along lines: K = 0 analytically");
    CHECK(cylinder_discrete <= 1e-9, "cylinders along lines: K = 0 by OpenMesh and VTK");
    CHECK(torus_dev <= 1e-12, "tori along arcs: K of the exact torus");
    CHECK(torus_samples > 0 && torus_discrete <= 0.05, "OpenMesh and VTK see the torus's K (discretization)");
    CHECK(straight_cos <= 1e-12, "parameter lines orthogonal on lines and arcs");
    CHECK(nurbs_cos <= 1e-6, "parameter lines orthogonal on the NURBS edge (rational RMF)");
    rmf_shape_free(shape);
    rmf_curve_free(profile);
    rmf_curve_free(nurbs);
    return rmf_check_exit_code("geometry_wire");
}
