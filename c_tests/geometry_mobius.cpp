/*
 * Developable strips and pipes along a Möbius spline (Bartoň, Jüttler & Wang, Fig. 3 and
 * item 5 of the issue): the ruled surface x(u) + v f2(u) of an exact RMF vector is
 * developable, and a circle swept with an exact RMF has orthogonal parameter lines (a
 * profile surface). Checked from the exported NURBS with the suite's own evaluator,
 * OpenMesh and VTK.
 */
#include "surface_checks.hpp"

extern "C" {
#include "rmf_check.h"
}

using rmf_checks::check_surface;
using rmf_checks::print_report;

static RmfCurve *line_profile(double width) {
    const RmfVec3 poles[2] = {{0, 0, 0}, {width, 0, 0}};
    const double knots[4] = {0, 0, 1, 1};
    RmfCurve *c = nullptr;
    CHECK_STATUS(rmf_nurbs_curve_create(1, poles, nullptr, 2, knots, 4, &c), RMF_OK, "");
    return c;
}

static RmfCurve *circle_profile(double r) {
    const double s = std::sqrt(0.5);
    const double ring[9][3] = {{1, 0, 1}, {1, 1, s}, {0, 1, 1}, {-1, 1, s}, {-1, 0, 1}, {-1, -1, s}, {0, -1, 1}, {1, -1, s}, {1, 0, 1}};
    const double knots[12] = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
    RmfVec3 poles[9];
    double weights[9];
    for (int i = 0; i < 9; ++i) {
        poles[i] = RmfVec3{r * ring[i][0], r * ring[i][1], 0};
        weights[i] = ring[i][2];
    }
    RmfCurve *c = nullptr;
    CHECK_STATUS(rmf_nurbs_curve_create(2, poles, weights, 9, knots, 12, &c), RMF_OK, "");
    return c;
}

int main() {
    RmfVec3 points[7], tangents[7];
    for (int i = 0; i < 7; ++i) {
        const double t = 0.7 * i;
        points[i] = RmfVec3{std::cos(t) + 0.1 * t * t, std::sin(t), 0.4 * t};
        tangents[i] = RmfVec3{-std::sin(t) + 0.2 * t, std::cos(t), 0.4};
    }
    RmfCurve *spine = nullptr;
    RmfFrames *frames = nullptr;
    CHECK_STATUS(rmf_mobius_rrmf_hermite(points, tangents, 7, RmfVec3{0, 0, 1}, &spine, &frames), RMF_OK, "");
    RmfCurve *line = line_profile(0.3), *circle = circle_profile(0.15);
    if (!spine || !frames || !line || !circle) return rmf_check_exit_code("geometry_mobius");

    RmfSurface *strip = nullptr, *pipe = nullptr;
    CHECK_STATUS(rmf_sweep_surface(spine, frames, line, &strip), RMF_OK, "");
    CHECK_STATUS(rmf_sweep_surface(spine, frames, circle, &pipe), RMF_OK, "");
    if (!strip || !pipe) return rmf_check_exit_code("geometry_mobius");
    RmfNurbsSurface view;
    rmf_surface_nurbs(strip, &view);
    const auto s = check_surface(view, 4, 12);
    std::printf("Möbius spline strip: degree (%u, %u), %zu x %zu poles\n", view.degree_u, view.degree_v,
                view.pole_count_u, view.pole_count_v);
    print_report("Möbius RMF strip x + v f2", s);
    CHECK(s.max_k_analytic < 1e-7, "the RMF strip is developable (analytic K)");
    CHECK(s.max_defect < 1e-7, "the RMF strip is developable (OpenMesh angle defect)");
    CHECK(s.max_k_vtk < 1e-5, "the RMF strip is developable (vtkCurvatures)");
    rmf_surface_nurbs(pipe, &view);
    const auto p = check_surface(view, 8, 12);
    print_report("Möbius RMF pipe (circle)", p);
    CHECK(p.max_cos < 1e-9, "parameter lines of the RMF pipe are orthogonal");

    rmf_surface_free(strip);
    rmf_surface_free(pipe);
    rmf_curve_free(line);
    rmf_curve_free(circle);
    rmf_frames_free(frames);
    rmf_curve_free(spine);
    return rmf_check_exit_code("geometry_mobius");
}
