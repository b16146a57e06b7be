/*
 * An independent NURBS evaluator for the test suite: it reads the NURBS views the library
 * exports and evaluates them with its own code (Piegl & Tiller, The NURBS Book, A2.1 span
 * search, A2.3 basis-function derivatives, A4.2/A4.4 rational derivatives), never with
 * rmf_*_eval. Valid C99 and C++.
 */
#ifndef RMF_TEST_NURBS_EVAL_H
#define RMF_TEST_NURBS_EVAL_H

#include "rmfsurf.h"

#ifdef __cplusplus
extern "C" {
#endif

#define NE_MAX_DEGREE 64

/* Point and derivatives of a curve at t: d[0] = C(t), d[1] = C'(t), d[2] = C''(t). */
void ne_curve_derivatives(const RmfNurbsCurve *curve, double t, RmfVec3 d[3]);

/* Partial derivatives of a surface at (u, v): d[k][l] = ∂^(k+l) S / ∂u^k ∂v^l, k + l ≤ 2. */
void ne_surface_derivatives(const RmfNurbsSurface *surface, double u, double v, RmfVec3 d[3][3]);

/* Gaussian curvature (LN − M²)/(EG − F²) from the derivatives above. */
double ne_gaussian_curvature(RmfVec3 d[3][3]);

/* |cos| of the angle between the parameter lines, |S_u · S_v| / (|S_u| |S_v|). */
double ne_parameter_line_cosine(RmfVec3 d[3][3]);

/* Point of a rational Bézier segment at local parameter s ∈ [0, 1] (de Casteljau). */
RmfVec3 ne_bezier_point(const RmfBezierCurve *segment, double s);

/* Small vector helpers. */
RmfVec3 ne_add(RmfVec3 a, RmfVec3 b);
RmfVec3 ne_sub(RmfVec3 a, RmfVec3 b);
RmfVec3 ne_scale(RmfVec3 a, double s);
RmfVec3 ne_unit(RmfVec3 a);
RmfVec3 ne_cross(RmfVec3 a, RmfVec3 b);
double ne_dot(RmfVec3 a, RmfVec3 b);
double ne_norm(RmfVec3 a);
double ne_dist(RmfVec3 a, RmfVec3 b);

#ifdef __cplusplus
}
#endif

#endif
