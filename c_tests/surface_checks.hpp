/*
 * Independent surface checks on an RmfNurbsSurface view, shared by the C++ geometry tests:
 *
 *  - the surface is evaluated with the suite's own NURBS code (nurbs_eval.c), never with
 *    rmf_surface_eval, on a grid refined inside every knot span (so patch boundaries, e.g.
 *    rulings, are mesh lines);
 *  - analytic measures from the NURBS derivatives: max |cos| between parameter lines (the
 *    O(u, v) of Mäurer & Jüttler (43)) and max |K| (Gaussian curvature);
 *  - discrete Gaussian curvature on the triangulated grid, at interior vertices only, with
 *    OpenMesh (angle defect 2π − Σ sector angles, and defect / (area / 3)) and with VTK
 *    (vtkCurvatures in Gaussian mode).
 *
 * Curvatures are reported scaled by size², size = bounding-box diagonal, so figures do not
 * depend on units.
 */
#ifndef RMF_TEST_SURFACE_CHECKS_HPP
#define RMF_TEST_SURFACE_CHECKS_HPP

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <vtkCellArray.h>
#include <vtkCurvatures.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "nurbs_eval.h"

namespace rmf_checks {

typedef OpenMesh::TriMesh_ArrayKernelT<OpenMesh::DefaultTraitsDouble> TriMesh;

struct SurfaceReport {
    double size = 0;              // bounding-box diagonal of the sampled points
    double max_cos = 0;           // max |cos ∠(s_u, s_v)|, analytic
    double max_k_analytic = 0;    // max |K| · size², analytic
    double min_k_analytic = 0;    // min |K| · size² over the interior vertices, analytic
    double max_defect = 0;        // max |2π − Σ angles| at interior vertices (OpenMesh), radians
    double max_k_openmesh = 0;    // max |defect / (area/3)| · size² (OpenMesh)
    double max_k_vtk = 0;         // max |K| · size² (vtkCurvatures) at interior vertices
    double max_dev_openmesh = 0;  // max |K_openmesh − K_analytic| · size²
    double max_dev_vtk = 0;       // max |K_vtk − K_analytic| · size²
    size_t interior_vertices = 0;
};

/* Distinct knots of a clamped knot vector, each interval split into `steps` parts. */
inline std::vector<double> grid_parameters(const double *knots, size_t count, int steps) {
    std::vector<double> breaks(knots, knots + count);
    breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
    std::vector<double> params;
    for (size_t k = 0; k + 1 < breaks.size(); ++k)
        for (int s = 0; s < steps; ++s) params.push_back(breaks[k] + (breaks[k + 1] - breaks[k]) * s / steps);
    params.push_back(breaks.back());
    return params;
}

/* The checks on the grid of the parameters `us` × `vs` (e.g. away from a singular row). */
inline SurfaceReport check_surface_at(const RmfNurbsSurface &surface, const std::vector<double> &us,
                                      const std::vector<double> &vs) {
    SurfaceReport r;
    const size_t rows = us.size(), cols = vs.size();
    std::vector<RmfVec3> points(rows * cols);
    std::vector<double> k_analytic(rows * cols);
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for (size_t i = 0; i < rows; ++i)
        for (size_t j = 0; j < cols; ++j) {
            RmfVec3 d[3][3];
            ne_surface_derivatives(&surface, us[i], vs[j], d);
            points[i * cols + j] = d[0][0];
            k_analytic[i * cols + j] = ne_gaussian_curvature(d);
            r.max_cos = std::max(r.max_cos, ne_parameter_line_cosine(d));
            const double c[3] = {d[0][0].x, d[0][0].y, d[0][0].z};
            for (int a = 0; a < 3; ++a) {
                lo[a] = std::min(lo[a], c[a]);
                hi[a] = std::max(hi[a], c[a]);
            }
        }
    r.size = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                       (hi[2] - lo[2]) * (hi[2] - lo[2]));
    const double s2 = r.size * r.size;
    for (double k : k_analytic) r.max_k_analytic = std::max(r.max_k_analytic, std::fabs(k) * s2);

    // OpenMesh: the same grid, two triangles per cell.
    TriMesh mesh;
    std::vector<TriMesh::VertexHandle> vh(points.size());
    for (size_t k = 0; k < points.size(); ++k)
        vh[k] = mesh.add_vertex(TriMesh::Point(points[k].x, points[k].y, points[k].z));
    vtkNew<vtkPoints> vtk_points;
    vtk_points->SetDataTypeToDouble();
    for (const RmfVec3 &p : points) vtk_points->InsertNextPoint(p.x, p.y, p.z);
    vtkNew<vtkCellArray> vtk_triangles;
    for (size_t i = 0; i + 1 < rows; ++i)
        for (size_t j = 0; j + 1 < cols; ++j) {
            const size_t a = i * cols + j, b = (i + 1) * cols + j, c = (i + 1) * cols + j + 1, d = i * cols + j + 1;
            mesh.add_face(vh[a], vh[b], vh[c]);
            mesh.add_face(vh[a], vh[c], vh[d]);
            const vtkIdType t1[3] = {(vtkIdType)a, (vtkIdType)b, (vtkIdType)c};
            const vtkIdType t2[3] = {(vtkIdType)a, (vtkIdType)c, (vtkIdType)d};
            vtk_triangles->InsertNextCell(3, t1);
            vtk_triangles->InsertNextCell(3, t2);
        }
    vtkNew<vtkPolyData> poly;
    poly->SetPoints(vtk_points);
    poly->SetPolys(vtk_triangles);
    vtkNew<vtkCurvatures> curvatures;
    curvatures->SetInputData(poly);
    curvatures->SetCurvatureTypeToGaussian();
    curvatures->Update();
    vtkDataArray *gauss = curvatures->GetOutput()->GetPointData()->GetArray("Gauss_Curvature");

    r.min_k_analytic = 1e300;
    for (size_t i = 1; i + 1 < rows; ++i)
        for (size_t j = 1; j + 1 < cols; ++j) {
            const size_t k = i * cols + j;
            const TriMesh::VertexHandle v = vh[k];
            if (mesh.is_boundary(v)) continue;
            double angles = 0, area = 0;
            for (TriMesh::HalfedgeHandle h : mesh.vih_range(v)) {
                if (mesh.is_boundary(h)) continue;
                angles += mesh.calc_sector_angle(h);
                area += mesh.calc_sector_area(h);
            }
            const double defect = 2 * M_PI - angles;
            const double k_openmesh = defect / (area / 3);
            const double k_vtk = gauss ? gauss->GetTuple1((vtkIdType)k) : 1e300;
            r.max_defect = std::max(r.max_defect, std::fabs(defect));
            r.max_k_openmesh = std::max(r.max_k_openmesh, std::fabs(k_openmesh) * s2);
            r.max_k_vtk = std::max(r.max_k_vtk, std::fabs(k_vtk) * s2);
            r.max_dev_openmesh = std::max(r.max_dev_openmesh, std::fabs(k_openmesh - k_analytic[k]) * s2);
            r.max_dev_vtk = std::max(r.max_dev_vtk, std::fabs(k_vtk - k_analytic[k]) * s2);
            r.min_k_analytic = std::min(r.min_k_analytic, std::fabs(k_analytic[k]) * s2);
            r.interior_vertices++;
        }
    return r;
}

inline SurfaceReport check_surface(const RmfNurbsSurface &surface, int steps_u, int steps_v) {
    return check_surface_at(surface, grid_parameters(surface.knots_u, surface.knot_count_u, steps_u),
                            grid_parameters(surface.knots_v, surface.knot_count_v, steps_v));
}

inline void print_report(const char *name, const SurfaceReport &r) {
    std::printf("%-28s max|cos| %.3e  max|K|s^2 analytic %.3e  OpenMesh: max defect %.3e rad, max|K|s^2 %.3e"
                "  VTK: max|K|s^2 %.3e  (%zu interior vertices, size %.3g)\n",
                name, r.max_cos, r.max_k_analytic, r.max_defect, r.max_k_openmesh, r.max_k_vtk,
                r.interior_vertices, r.size);
}

}  // namespace rmf_checks

#endif
