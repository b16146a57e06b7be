/*
 * C99 tests of the PH cubic API (Mäurer & Jüttler): Hermite interpolation (Table 1), splines,
 * approximation with the order-4 table of Theorem 10, rational and exact RMFs, twist and
 * closure, accuracy reports, profile-surface analysis and offsets — good input checked with the
 * suite's own NURBS evaluator (nurbs_eval.c), bad input each with its status code, a message
 * naming the argument and untouched out-pointers. Runs under valgrind (no leaks).
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "nurbs_eval.h"
#include "rmf_check.h"

#define PI 3.14159265358979323846


/* ---- analytic curves ---- */

/* The helix (cos t, sin t, pitch t); user points to the pitch. */
static void helix(double t, void *user, RmfVec3 *point, RmfVec3 *tangent) {
    double pitch = *(const double *)user;
    *point = vec3(cos(t), sin(t), pitch * t);
    *tangent = vec3(-sin(t), cos(t), pitch);
}

/* The twisted cubic (t, t², t³): not a helix (κ/τ is not constant). */
static void twisted_cubic(double t, void *user, RmfVec3 *point, RmfVec3 *tangent) {
    (void)user;
    *point = vec3(t, t * t, t * t * t);
    *tangent = vec3(1, 2 * t, 3 * t * t);
}

/* A trefoil knot, closed over [0, 2π]. */
static void trefoil(double t, void *user, RmfVec3 *point, RmfVec3 *tangent) {
    (void)user;
    *point = vec3(sin(t) + 2 * sin(2 * t), cos(t) - 2 * cos(2 * t), -sin(3 * t));
    *tangent = vec3(cos(t) + 4 * cos(2 * t), -sin(t) + 4 * sin(2 * t), -3 * cos(3 * t));
}

/* A callback that writes nothing usable. */
static void broken(double t, void *user, RmfVec3 *point, RmfVec3 *tangent) {
    (void)user;
    *point = vec3(t, nan_value(), 0);
    *tangent = vec3(1, 0, 0);
}

typedef void (*Analytic)(double, void *, RmfVec3 *, RmfVec3 *);

/* The PH spline through n + 1 samples of a curve at uniform parameters on [a, b]. */
static RmfCurve *spline_through(Analytic f, void *user, double a, double b, int n) {
    RmfVec3 points[129], tangents[129];
    RmfCurve *c = NULL;
    int i;
    for (i = 0; i <= n; i++) f(a + (b - a) * i / n, user, &points[i], &tangents[i]);
    CHECK_STATUS(rmf_ph_spline_hermite(points, tangents, (size_t)n + 1, &c), RMF_OK, "");
    return c;
}

/* Distance from p to a NURBS curve near [t0, t1]: best of 16 samples, then Newton on
 * (C(t) − p)·C'(t) = 0, all with the suite's evaluator. */
static double distance_to(const RmfNurbsCurve *view, RmfVec3 p, double t0, double t1) {
    double best_t = t0, best = 1e300, t;
    int i;
    RmfVec3 d[3];
    for (i = 0; i <= 16; i++) {
        t = t0 + (t1 - t0) * i / 16.0;
        ne_curve_derivatives(view, t, d);
        if (ne_dist(d[0], p) < best) best = ne_dist(d[0], p), best_t = t;
    }
    t = best_t;
    for (i = 0; i < 20; i++) {
        RmfVec3 r;
        double f, df;
        ne_curve_derivatives(view, t, d);
        r = ne_sub(d[0], p);
        f = ne_dot(r, d[1]);
        df = ne_dot(d[1], d[1]) + ne_dot(r, d[2]);
        t -= f / df;
        if (t < t0) t = t0;
        if (t > t1) t = t1;
    }
    ne_curve_derivatives(view, t, d);
    return ne_dist(d[0], p) < best ? ne_dist(d[0], p) : best;
}

/* Largest distance from 20 points per segment of the analytic curve to the spline (segment i
 * on [i, i + 1] of the spline, on [a + i h, a + (i + 1) h] of the curve). */
static double spline_error(const RmfCurve *spline, Analytic f, void *user, double a, double b, int n) {
    RmfNurbsCurve view;
    double worst = 0;
    int i, j;
    CHECK_STATUS(rmf_curve_nurbs(spline, &view), RMF_OK, "");
    for (i = 0; i < n; i++)
        for (j = 1; j < 20; j++) {
            RmfVec3 p, d;
            double e;
            f(a + (b - a) * (i + j / 20.0) / n, user, &p, &d);
            e = distance_to(&view, p, i, i + 1);
            if (e > worst) worst = e;
        }
    return worst;
}

/* ---- Hermite interpolation ---- */

/* |x'| of a PH cubic is a quadratic polynomial: the values at 0, 1/2, 1 predict the rest. */
static double speed_residual(const RmfCurve *c) {
    RmfNurbsCurve view;
    RmfVec3 d[3];
    double s0, sh, s1, worst = 0, t;
    int i;
    CHECK_STATUS(rmf_curve_nurbs(c, &view), RMF_OK, "");
    ne_curve_derivatives(&view, 0, d), s0 = ne_norm(d[1]);
    ne_curve_derivatives(&view, 0.5, d), sh = ne_norm(d[1]);
    ne_curve_derivatives(&view, 1, d), s1 = ne_norm(d[1]);
    for (i = 0; i <= 20; i++) {
        double predicted, e;
        t = i / 20.0;
        predicted = s0 * (1 - t) * (1 - 2 * t) + 4 * sh * t * (1 - t) + s1 * t * (2 * t - 1);
        ne_curve_derivatives(&view, t, d);
        e = fabs(ne_norm(d[1]) - predicted) / s0;
        if (e > worst) worst = e;
    }
    return worst;
}

static void test_hermite(void) {
    RmfVec3 p0 = vec3(0, 0, 0), t0 = vec3(1, 0.3, 0.1), p1 = vec3(2, 1, 0.4), t1 = vec3(0.4, 1, 0.3);
    RmfCurve *a = NULL, *b = NULL, *sentinel = (RmfCurve *)&p0, *untouched = sentinel;
    RmfNurbsCurve view;
    RmfVec3 d[3];

    CHECK_STATUS(rmf_ph_cubic_hermite(p0, t0, p1, t1, &a, &b), RMF_OK, "");
    CHECK(a && b, "two interpolants");
    if (a && b) {
        const RmfCurve *both[2];
        double length[2];
        int k;
        both[0] = a, both[1] = b;
        for (k = 0; k < 2; k++) {
            size_t i;
            CHECK_STATUS(rmf_curve_nurbs(both[k], &view), RMF_OK, "");
            CHECK(view.degree == 3 && view.pole_count == 4, "one cubic Bézier segment");
            ne_curve_derivatives(&view, 0, d);
            CHECK(ne_dist(d[0], p0) < 1e-15 && ne_dist(ne_unit(d[1]), ne_unit(t0)) < 1e-12, "starts at p0 along +t0");
            ne_curve_derivatives(&view, 1, d);
            CHECK(ne_dist(d[0], p1) < 1e-15 && ne_dist(ne_unit(d[1]), ne_unit(t1)) < 1e-12, "ends at p1 along +t1");
            CHECK(speed_residual(both[k]) < 1e-12, "Pythagorean hodograph: |x'| is quadratic");
            for (length[k] = 0, i = 1; i < 4; i++) length[k] += ne_dist(view.poles[i], view.poles[i - 1]);
        }
        CHECK(length[0] < length[1], "the shape-matching interpolant has the shorter control polygon");
    }
    rmf_curve_free(a);
    rmf_curve_free(b);

    /* Planar data give a planar cubic; "other" may be omitted. */
    a = NULL;
    CHECK_STATUS(rmf_ph_cubic_hermite(vec3(0, 0, 0), vec3(1, 0, 0), vec3(1, 1, 0), vec3(0, 1, 0), &a, NULL), RMF_OK,
                 "");
    if (a) {
        size_t i;
        CHECK_STATUS(rmf_curve_nurbs(a, &view), RMF_OK, "");
        for (i = 0; i < view.pole_count; i++) CHECK(view.poles[i].z == 0.0, "planar data, planar cubic");
    }
    rmf_curve_free(a);

    /* Opposite tangents: one U-turn, the other root reverses both tangents. */
    a = NULL, b = sentinel;
    CHECK_STATUS(rmf_ph_cubic_hermite(vec3(0, 0, 0), vec3(1, 0, 0), vec3(0.5, 2, 0), vec3(-1, 0, 0), &a, &b), RMF_OK,
                 "");
    CHECK(a != NULL && b == NULL, "one U-turn, no second interpolant");
    rmf_curve_free(a);

    /* Bad input: nothing is written. */
    a = untouched;
    CHECK_STATUS(rmf_ph_cubic_hermite(p0, t0, p1, t1, NULL, &b), RMF_ERROR_NULL_POINTER, "shape_matching");
    CHECK_STATUS(rmf_ph_cubic_hermite(vec3(nan_value(), 0, 0), t0, p1, t1, &a, NULL), RMF_ERROR_INVALID_INPUT, "p0");
    CHECK_STATUS(rmf_ph_cubic_hermite(p0, vec3(0, 0, 0), p1, t1, &a, NULL), RMF_ERROR_INVALID_INPUT, "t0");
    CHECK_STATUS(rmf_ph_cubic_hermite(p0, t0, p1, vec3(inf_value(), 0, 0), &a, NULL), RMF_ERROR_INVALID_INPUT, "t1");
    CHECK_STATUS(rmf_ph_cubic_hermite(p0, t0, p0, t1, &a, NULL), RMF_ERROR_INVALID_INPUT, "p0 and p1 coincide");
    CHECK_STATUS(rmf_ph_cubic_hermite(p0, vec3(1, 0, 0), vec3(3, 1, 0), vec3(1, 0, 0), &a, NULL),
                 RMF_ERROR_NO_SOLUTION, "parallel");
    CHECK_STATUS(rmf_ph_cubic_hermite(p0, vec3(1, 0.01, 0), vec3(1, 1, 0), vec3(1, 0, 0), &a, NULL),
                 RMF_ERROR_NO_SOLUTION, "(*)");
    CHECK(a == untouched, "a failing call leaves the out-pointer alone");
}

/* ---- splines and Theorem 10 ---- */

static void test_spline_hermite(void) {
    RmfVec3 points[9], tangents[9];
    RmfCurve *c = NULL, *untouched = (RmfCurve *)points;
    RmfNurbsCurve view;
    double pitch = 0.4;
    int i;
    for (i = 0; i <= 8; i++) helix(0.5 * i, &pitch, &points[i], &tangents[i]);
    CHECK_STATUS(rmf_ph_spline_hermite(points, tangents, 9, &c), RMF_OK, "");
    if (c) {
        CHECK_STATUS(rmf_curve_nurbs(c, &view), RMF_OK, "");
        CHECK(view.degree == 3 && view.pole_count == 25 && view.knot_count == 29, "8 cubic segments as one NURBS");
        for (i = 0; i <= 8; i++) {
            RmfVec3 d[3];
            ne_curve_derivatives(&view, i, d);
            CHECK(ne_dist(d[0], points[i]) < 1e-14, "interpolates the points");
            CHECK(ne_dist(ne_unit(d[1]), ne_unit(tangents[i])) < 1e-12, "and the tangents (G1)");
        }
    }
    rmf_curve_free(c);

    c = untouched;
    CHECK_STATUS(rmf_ph_spline_hermite(points, tangents, 1, &c), RMF_ERROR_INVALID_INPUT, "at least 2");
    CHECK_STATUS(rmf_ph_spline_hermite(NULL, tangents, 9, &c), RMF_ERROR_NULL_POINTER, "points");
    CHECK_STATUS(rmf_ph_spline_hermite(points, NULL, 9, &c), RMF_ERROR_NULL_POINTER, "tangents");
    CHECK_STATUS(rmf_ph_spline_hermite(points, tangents, 9, NULL), RMF_ERROR_NULL_POINTER, "out");
    tangents[2] = vec3(0, nan_value(), 1);
    CHECK_STATUS(rmf_ph_spline_hermite(points, tangents, 9, &c), RMF_ERROR_INVALID_INPUT, "tangents[2]");
    tangents[2] = vec3(0, 0, 0);
    CHECK_STATUS(rmf_ph_spline_hermite(points, tangents, 9, &c), RMF_ERROR_INVALID_INPUT, "tangents[2]");
    helix(1.0, &pitch, &points[2], &tangents[2]);
    points[4] = points[3];
    CHECK_STATUS(rmf_ph_spline_hermite(points, tangents, 9, &c), RMF_ERROR_INVALID_INPUT, "points[3] and points[4]");
    /* Parallel tangents with the chord off their line: segment 1 has no PH cubic. */
    points[0] = vec3(0, 0, 0), points[1] = vec3(1, 0, 0), points[2] = vec3(2, 1, 0);
    tangents[0] = tangents[1] = tangents[2] = vec3(1, 0, 0);
    CHECK_STATUS(rmf_ph_spline_hermite(points, tangents, 3, &c), RMF_ERROR_NO_SOLUTION, "segment 1");
    CHECK(c == untouched, "a failing call leaves the out-pointer alone");
}

/* Theorem 10: max distance vs step h on two analytic curves, observed order ≈ 4. */
static void test_approximation_order(void) {
    struct {
        const char *name;
        Analytic f;
        double a, b;
    } curves[2];
    double pitch = 0.5;
    int k;
    curves[0].name = "helix (cos t, sin t, t/2), t in [0, 2pi]";
    curves[0].f = helix, curves[0].a = 0, curves[0].b = 2 * PI;
    curves[1].name = "twisted cubic (t, t^2, t^3), t in [0.2, 1.2]";
    curves[1].f = twisted_cubic, curves[1].a = 0.2, curves[1].b = 1.2;
    for (k = 0; k < 2; k++) {
        double previous = 0;
        int n;
        printf("Theorem 10 (PH spline through uniform samples), %s:\n   segments  h          max distance  order\n",
               curves[k].name);
        for (n = 4; n <= 64; n *= 2) {
            RmfCurve *c = spline_through(curves[k].f, &pitch, curves[k].a, curves[k].b, n);
            double e = c ? spline_error(c, curves[k].f, &pitch, curves[k].a, curves[k].b, n) : 1;
            double order = previous > 0 ? log(previous / e) / log(2.0) : 0;
            printf("   %8d  %.4e  %.4e    %s%.2f\n", n, (curves[k].b - curves[k].a) / n, e, previous > 0 ? "" : "(",
                   previous > 0 ? order : 0.0);
            if (n >= 16) CHECK(order > 3.6 && order < 4.4, "approximation order 4 (Theorem 10)");
            previous = e;
            rmf_curve_free(c);
        }
    }
}

static void test_spline_approximate(void) {
    double pitch = 0.5, d = -1;
    RmfCurve *c = NULL, *untouched = (RmfCurve *)&pitch, *nurbs = NULL;
    /* A rational NURBS input curve: two quadratic arcs, G1 at the joint. */
    static const RmfVec3 poles[5] = {{1, 0, 0}, {1, 1, 0.5}, {0, 1, 1}, {-1, 1, 1.5}, {-1, 0, 2}};
    static const double weights[5] = {1, 0.7, 1, 0.7, 1};
    static const double knots[8] = {0, 0, 0, 1, 1, 2, 2, 2};

    CHECK_STATUS(rmf_ph_spline_approximate(NULL, helix, &pitch, 0, 2 * PI, 1e-6, &c, &d), RMF_OK, "");
    CHECK(d > 0 && d <= 1e-6, "reported distance within the tolerance");
    if (c) {
        double lo, hi;
        size_t segments = 0;
        CHECK_STATUS(rmf_curve_domain(c, &lo, &hi), RMF_OK, "");
        CHECK(lo == 0 && hi == 2 * PI, "the spline keeps the curve's parameter domain");
        CHECK_STATUS(rmf_curve_segment_count(c, &segments), RMF_OK, "");
        printf("rmf_ph_spline_approximate: helix to 1e-6 with %zu PH cubics (max distance %.2e)\n", segments, d);
    }
    rmf_curve_free(c);

    CHECK_STATUS(rmf_nurbs_curve_create(2, poles, weights, 5, knots, 8, &nurbs), RMF_OK, "");
    c = NULL;
    CHECK_STATUS(rmf_ph_spline_approximate(nurbs, NULL, NULL, 0, 0, 1e-8, &c, NULL), RMF_OK, "");
    if (c) {
        /* Independent check: curve points against the spline, both evaluated by nurbs_eval. */
        RmfNurbsCurve input, spline;
        double worst = 0;
        int i;
        CHECK_STATUS(rmf_curve_nurbs(nurbs, &input), RMF_OK, "");
        CHECK_STATUS(rmf_curve_nurbs(c, &spline), RMF_OK, "");
        for (i = 0; i <= 400; i++) {
            RmfVec3 q[3];
            double t = 2.0 * i / 400, e;
            ne_curve_derivatives(&input, t, q);
            e = distance_to(&spline, q[0], t - 0.05 < 0 ? 0 : t - 0.05, t + 0.05 > 2 ? 2 : t + 0.05);
            if (e > worst) worst = e;
        }
        CHECK(worst <= 1.01e-8, "NURBS input followed within the tolerance");
        printf("rmf_ph_spline_approximate: rational NURBS input to 1e-8, measured max distance %.2e\n", worst);
    }
    rmf_curve_free(c);

    c = untouched;
    CHECK_STATUS(rmf_ph_spline_approximate(NULL, helix, &pitch, 0, 1, 0.0, &c, NULL), RMF_ERROR_INVALID_INPUT,
                 "tolerance");
    CHECK_STATUS(rmf_ph_spline_approximate(NULL, helix, &pitch, 0, 1, -1e-3, &c, NULL), RMF_ERROR_INVALID_INPUT,
                 "tolerance");
    CHECK_STATUS(rmf_ph_spline_approximate(NULL, helix, &pitch, 0, 1, nan_value(), &c, NULL), RMF_ERROR_INVALID_INPUT,
                 "tolerance");
    CHECK_STATUS(rmf_ph_spline_approximate(NULL, helix, &pitch, 0, 1, inf_value(), &c, NULL), RMF_ERROR_INVALID_INPUT,
                 "tolerance");
    CHECK_STATUS(rmf_ph_spline_approximate(NULL, NULL, NULL, 0, 1, 1e-3, &c, NULL), RMF_ERROR_NULL_POINTER, "curve");
    CHECK_STATUS(rmf_ph_spline_approximate(nurbs, helix, &pitch, 0, 1, 1e-3, &c, NULL), RMF_ERROR_INVALID_INPUT,
                 "either");
    CHECK_STATUS(rmf_ph_spline_approximate(NULL, helix, &pitch, 1, 1, 1e-3, &c, NULL), RMF_ERROR_INVALID_INPUT,
                 "t_min");
    CHECK_STATUS(rmf_ph_spline_approximate(NULL, broken, NULL, 0, 1, 1e-3, &c, NULL), RMF_ERROR_INVALID_INPUT,
                 "non-finite");
    CHECK_STATUS(rmf_ph_spline_approximate(NULL, helix, &pitch, 0, 1, 1e-3, NULL, NULL), RMF_ERROR_NULL_POINTER,
                 "out");
    {
        /* A corner at the joint of two lines. */
        static const RmfVec3 corner[3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
        static const double corner_knots[5] = {0, 0, 1, 2, 2};
        RmfCurve *kinked = NULL;
        CHECK_STATUS(rmf_nurbs_curve_create(1, corner, NULL, 3, corner_knots, 5, &kinked), RMF_OK, "");
        CHECK_STATUS(rmf_ph_spline_approximate(kinked, NULL, NULL, 0, 0, 1e-3, &c, NULL), RMF_ERROR_INVALID_INPUT,
                     "corner");
        rmf_curve_free(kinked);
    }
    CHECK(c == untouched, "a failing call leaves the out-pointer alone");
    rmf_curve_free(nurbs);
}

/* ---- frames ---- */

/* max |f2' · f3| / |x'| (the turn of the frame about the tangent per unit length; zero for an
 * exact RMF) along continuous rational frames, from the NURBS views of the frame vector f2
 * (its poles are the tips of unit vectors) and of the spline, evaluated by nurbs_eval. */
static double rmf_defect(const RmfCurve *spline, const RmfFrames *frames) {
    RmfCurve *f2 = NULL;
    RmfNurbsCurve f2_view, x_view;
    double lo, hi, worst = 0;
    int i, bad = 0;
    CHECK_STATUS(rmf_frames_vector_curve(frames, RMF_FRAME_F2, &f2), RMF_OK, "");
    if (!f2) return 1e300;
    CHECK_STATUS(rmf_curve_nurbs(f2, &f2_view), RMF_OK, "");
    CHECK_STATUS(rmf_curve_nurbs(spline, &x_view), RMF_OK, "");
    CHECK_STATUS(rmf_curve_domain(spline, &lo, &hi), RMF_OK, "");
    for (i = 0; i <= 997; i++) {
        double t = lo + (hi - lo) * i / 997.0, e;
        RmfVec3 x[3], f[3], f3;
        ne_curve_derivatives(&x_view, t, x);
        ne_curve_derivatives(&f2_view, t, f);
        f3 = ne_cross(ne_unit(x[1]), f[0]);
        bad += !(fabs(ne_norm(f[0]) - 1) < 1e-12 && fabs(ne_dot(f[0], x[1])) < 1e-12 * ne_norm(x[1]));
        e = fabs(ne_dot(f[1], f3)) / ne_norm(x[1]);
        if (e > worst) worst = e;
    }
    CHECK(bad == 0, "f2 is a unit normal vector");
    rmf_curve_free(f2);
    return worst;
}

/* The same for frames that jump at the joints (Frenet frames of a G1 spline have no single
 * NURBS): central differences of rmf_frames_eval inside the segments. */
static double turn_rate_inside_segments(const RmfCurve *spline, const RmfFrames *frames, int segments) {
    double worst = 0, h = 1e-6;
    int k, i;
    for (k = 0; k < segments; k++)
        for (i = 1; i < 20; i++) {
            double t = k + i / 20.0, e;
            RmfVec3 x, d, ta, a2, a3, tb, b2, b3, tc, c2, c3;
            rmf_curve_eval(spline, t, &x, &d);
            rmf_frames_eval(frames, t - h, &ta, &a2, &a3);
            rmf_frames_eval(frames, t, &tc, &c2, &c3);
            rmf_frames_eval(frames, t + h, &tb, &b2, &b3);
            e = fabs(ne_dot(ne_scale(ne_sub(b2, a2), 0.5 / h), c3)) / ne_norm(d);
            if (e > worst) worst = e;
        }
    return worst;
}

/* Largest angle between rational frames and the closed-form exact RMF at many parameters. */
static double exact_gap(const RmfCurve *spline, const RmfFrames *frames, RmfVec3 normal) {
    double t[501], lo, hi, worst = 0;
    RmfVec3 f2[501];
    int i;
    rmf_curve_domain(spline, &lo, &hi);
    for (i = 0; i <= 500; i++) t[i] = lo + (hi - lo) * i / 500.0;
    CHECK_STATUS(rmf_ph_exact_rmf_eval(spline, normal, t, 501, f2, NULL), RMF_OK, "");
    for (i = 0; i <= 500; i++) {
        RmfVec3 tangent, g2, g3;
        double angle;
        CHECK_STATUS(rmf_frames_eval(frames, t[i], &tangent, &g2, &g3), RMF_OK, "");
        angle = atan2(ne_norm(ne_cross(f2[i], g2)), ne_dot(f2[i], g2));
        if (angle > worst) worst = angle;
    }
    return worst;
}

static void print_angle_errors(const char *name, const RmfFrames *frames, double bound) {
    double errors[64], max_angle = -1;
    size_t n = 0, i;
    CHECK_STATUS(rmf_ph_rmf_angle_error(frames, errors, 64, &n, &max_angle), RMF_OK, "");
    printf("max angle rational RMF vs exact RMF, %s: %.3e rad; per segment:", name, max_angle);
    for (i = 0; i < n && i < 64; i++) printf(" %.2e", errors[i]);
    printf("\n");
    CHECK(max_angle >= 0 && max_angle < bound, "rational RMF close to the exact RMF");
}

static void test_rational_rmf(void) {
    double pitch = 0.4, max_angle = -1, dummy[2] = {-3, -3};
    RmfCurve *spline = spline_through(helix, &pitch, 0, 4.8, 8);
    RmfCurve *twisted = spline_through(twisted_cubic, NULL, 0.2, 1.4, 8);
    RmfFrames *rmf = NULL, *frenet = NULL, *other = NULL, *untouched = (RmfFrames *)&pitch;
    RmfVec3 normal = vec3(0, 0, 1);
    uint32_t kind = 99;
    size_t n = 0;
    if (!spline || !twisted) return;

    CHECK_STATUS(rmf_ph_rational_rmf(spline, normal, &rmf), RMF_OK, "");
    CHECK_STATUS(rmf_ph_frenet_frames(spline, &frenet), RMF_OK, "");
    if (rmf && frenet) {
        double defect_rmf = rmf_defect(spline, rmf), defect_frenet = turn_rate_inside_segments(spline, frenet, 8);
        double gap = exact_gap(spline, rmf, normal);
        RmfVec3 t, f2, f3;
        CHECK_STATUS(rmf_frames_kind(rmf, &kind), RMF_OK, "");
        CHECK(kind == RMF_FRAMES_RATIONAL, "rational frames");
        CHECK_STATUS(rmf_frames_eval(rmf, 0, &t, &f2, &f3), RMF_OK, "");
        CHECK(ne_dist(f2, ne_unit(ne_sub(normal, ne_scale(t, ne_dot(normal, t))))) < 1e-14,
              "f2 starts at the initial normal projected onto the normal plane");
        printf("turn about the tangent |f2'.f3|/|x'| on the helix spline (torsion 0.345): rational RMF %.2e, Frenet "
               "%.3f rad per unit length\n",
               defect_rmf, defect_frenet);
        CHECK(defect_frenet > 0.3 && defect_rmf < 1e-4 * defect_frenet,
              "the rational RMF turns 1e4 times less than the Frenet frame");
        printf("rational RMF vs closed-form exact RMF (rmf_ph_exact_rmf_eval), helix spline: %.3e rad\n", gap);
        CHECK(gap < 1e-5, "rational RMF close to the exact RMF");
        print_angle_errors("helix spline (8 segments, 0.6 rad each)", rmf, 2e-6);
    }
    CHECK_STATUS(rmf_ph_rational_rmf(twisted, vec3(1, 0, 0), &other), RMF_OK, "");
    if (other) print_angle_errors("twisted-cubic spline (8 segments)", other, 1e-6);
    rmf_frames_free(other);
    other = NULL;

    /* Accuracy report: size query, small buffer, frames that are not rational. */
    if (rmf) {
        CHECK_STATUS(rmf_ph_rmf_angle_error(rmf, NULL, 0, &n, &max_angle), RMF_OK, "");
        CHECK(n == 8 && max_angle > 0, "size query reports 8 segments");
        n = 0;
        CHECK_STATUS(rmf_ph_rmf_angle_error(rmf, dummy, 2, &n, &max_angle), RMF_ERROR_BUFFER_TOO_SMALL, "8");
        CHECK(n == 8 && dummy[0] == -3, "needed size reported, buffer untouched");
        CHECK_STATUS(rmf_ph_rmf_angle_error(rmf, dummy, 2, NULL, &max_angle), RMF_ERROR_NULL_POINTER,
                     "segment_count");
        CHECK_STATUS(rmf_ph_rmf_angle_error(NULL, dummy, 2, &n, &max_angle), RMF_ERROR_NULL_POINTER, "frames");
    }
    {
        RmfFrames *sampled = NULL;
        CHECK_STATUS(rmf_double_reflection_frames(spline, normal, 100, &sampled), RMF_OK, "");
        CHECK_STATUS(rmf_ph_rmf_angle_error(sampled, NULL, 0, &n, &max_angle), RMF_ERROR_INVALID_INPUT, "rational");
        rmf_frames_free(sampled);
    }

    /* Bad input to the constructors. */
    other = untouched;
    CHECK_STATUS(rmf_ph_rational_rmf(NULL, normal, &other), RMF_ERROR_NULL_POINTER, "ph_spline");
    CHECK_STATUS(rmf_ph_rational_rmf(spline, normal, NULL), RMF_ERROR_NULL_POINTER, "out");
    CHECK_STATUS(rmf_ph_rational_rmf(spline, vec3(nan_value(), 0, 1), &other), RMF_ERROR_INVALID_INPUT,
                 "initial_normal");
    CHECK_STATUS(rmf_ph_rational_rmf(spline, vec3(0, 0, 0), &other), RMF_ERROR_INVALID_INPUT, "initial_normal");
    CHECK_STATUS(rmf_ph_rational_rmf(spline, vec3(0, 1, 0.4), &other), RMF_ERROR_INVALID_INPUT, "initial_normal");
    CHECK_STATUS(rmf_ph_rational_rmf_twisted(spline, normal, nan_value(), 0, &other), RMF_ERROR_INVALID_INPUT,
                 "twist");
    CHECK_STATUS(rmf_ph_rational_rmf_twisted(spline, normal, 0, 1, &other), RMF_ERROR_INVALID_INPUT, "closed");
    CHECK_STATUS(rmf_ph_frenet_frames(NULL, &other), RMF_ERROR_NULL_POINTER, "ph_spline");
    {
        /* A cubic NURBS that is not PH, and a straight PH spline (no Frenet frame). */
        static const RmfVec3 poles[4] = {{0, 0, 0}, {1, 0, 0}, {2, 1, 0}, {3, 1, 1}};
        static const RmfVec3 line[4] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}};
        static const double knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
        RmfCurve *generic = NULL, *straight = NULL;
        CHECK_STATUS(rmf_nurbs_curve_create(3, poles, NULL, 4, knots, 8, &generic), RMF_OK, "");
        CHECK_STATUS(rmf_ph_rational_rmf(generic, normal, &other), RMF_ERROR_INVALID_INPUT, "PH condition (17)");
        CHECK_STATUS(rmf_nurbs_curve_create(3, line, NULL, 4, knots, 8, &straight), RMF_OK, "");
        CHECK_STATUS(rmf_ph_frenet_frames(straight, &other), RMF_ERROR_INVALID_INPUT, "straight");
        {
            /* Its RMF is the constant frame. */
            RmfFrames *constant = NULL;
            RmfVec3 t, f2, f3;
            CHECK_STATUS(rmf_ph_rational_rmf(straight, vec3(0, 1, 1), &constant), RMF_OK, "");
            if (constant) {
                CHECK_STATUS(rmf_frames_eval(constant, 0.7, &t, &f2, &f3), RMF_OK, "");
                CHECK(ne_dist(f2, ne_unit(vec3(0, 1, 1))) < 1e-15, "a straight spine carries its frame unchanged");
            }
            rmf_frames_free(constant);
        }
        rmf_curve_free(generic);
        rmf_curve_free(straight);
    }
    {
        double t = 9.0;
        RmfVec3 f2;
        CHECK_STATUS(rmf_ph_exact_rmf_eval(spline, normal, &t, 1, &f2, NULL), RMF_ERROR_INVALID_INPUT, "t = 9");
        CHECK_STATUS(rmf_ph_exact_rmf_eval(spline, normal, &t, 1, NULL, NULL), RMF_ERROR_NULL_POINTER, "f2");
        CHECK_STATUS(rmf_ph_exact_rmf_eval(spline, normal, NULL, 0, NULL, NULL), RMF_OK, "");
    }
    CHECK(other == untouched, "a failing call leaves the out-pointer alone");
    rmf_frames_free(rmf);
    rmf_frames_free(frenet);
    rmf_curve_free(spline);
    rmf_curve_free(twisted);
}

/* The turn about the common tangent from frame a to frame b. */
static double turn(RmfVec3 t, RmfVec3 a, RmfVec3 b) { return atan2(ne_dot(ne_cross(a, b), t), ne_dot(a, b)); }

static void test_closed_spine(void) {
    RmfCurve *loop = spline_through(trefoil, NULL, 0, 2 * PI, 24);
    RmfFrames *open = NULL, *closed = NULL, *square = NULL, *twisted = NULL;
    RmfVec3 normal = vec3(0, 0, 1);
    if (!loop) return;
    CHECK_STATUS(rmf_ph_rational_rmf(loop, normal, &open), RMF_OK, "");
    CHECK_STATUS(rmf_ph_rational_rmf_twisted(loop, normal, 0, 1, &closed), RMF_OK, "");
    CHECK_STATUS(rmf_ph_rational_rmf_twisted(loop, normal, 0, 4, &square), RMF_OK, "");
    CHECK_STATUS(rmf_ph_rational_rmf_twisted(loop, normal, 2 * PI, 1, &twisted), RMF_OK, "");
    if (open && closed && square && twisted) {
        RmfVec3 t0, a0, b0, t1, a1, b1;
        double holonomy, gap, quarter;
        rmf_frames_eval(open, 0, &t0, &a0, &b0);
        rmf_frames_eval(open, 24, &t1, &a1, &b1);
        holonomy = turn(t0, a0, a1);
        rmf_frames_eval(closed, 24, &t1, &a1, &b1);
        gap = turn(t0, a0, a1);
        rmf_frames_eval(square, 24, &t1, &a1, &b1);
        quarter = turn(t0, a0, a1);
        printf("closed trefoil spine (24 PH cubics): RMF holonomy %.6f rad; closed frame gap %.1e rad; "
               "square-profile closure turn %.6f rad (a multiple of pi/2)\n",
               holonomy, gap, quarter);
        CHECK(fabs(holonomy) > 1.0, "the RMF of the trefoil does not close");
        CHECK(fabs(gap) < 1e-12, "closure: the frame closes");
        CHECK(fabs(quarter - PI / 2 * floor(quarter / (PI / 2) + 0.5)) < 1e-12, "closure modulo 90 degrees");
        rmf_frames_eval(twisted, 24, &t1, &a1, &b1);
        CHECK(fabs(turn(t0, a0, a1)) < 1e-12, "a full extra turn still closes");
        print_angle_errors("closed trefoil (24 segments), closure turn taken off", closed, 1e-4);
    }
    rmf_frames_free(open);
    rmf_frames_free(closed);
    rmf_frames_free(square);
    rmf_frames_free(twisted);
    rmf_curve_free(loop);
}

/* ---- profile surfaces: sweep, analysis, offsets ---- */

static RmfCurve *arc_profile(double r) {
    const RmfVec3 poles[3] = {{r, 0, 0}, {r, r, 0}, {0, r, 0}};
    const double weights[3] = {1, sqrt(0.5), 1}, knots[6] = {0, 0, 0, 1, 1, 1};
    RmfCurve *c = NULL;
    CHECK_STATUS(rmf_nurbs_curve_create(2, poles, weights, 3, knots, 6, &c), RMF_OK, "");
    return c;
}

/* The offset at distance d of the ellipse (2 cos t, sin t) along (y', -x')/|c'|. */
static RmfVec3 ellipse_offset(double t, double d) {
    double n = sqrt(cos(t) * cos(t) + 4 * sin(t) * sin(t));
    RmfVec3 p = {2 * cos(t) + d * cos(t) / n, sin(t) + d * 2 * sin(t) / n, 0};
    return p;
}

static void test_profile_surface_analysis(void) {
    double pitch = 0.4, k = 0, margin = -1;
    RmfCurve *spine = spline_through(helix, &pitch, 0, 2.4, 4), *small = arc_profile(0.3), *big = arc_profile(2.0);
    RmfCurve *offset = NULL, *ellipse = NULL, *untouched = (RmfCurve *)&pitch;
    RmfFrames *rmf = NULL;
    RmfSurface *surface = NULL;
    RmfSingularityMargin m;
    RmfParabolicPoint points[256];
    RmfVec3 start;
    size_t count = 0;
    if (!spine || !small || !big) return;
    CHECK_STATUS(rmf_ph_rational_rmf(spine, vec3(0, 0, 1), &rmf), RMF_OK, "");
    if (!rmf) return;

    /* The profile surface (42) of a circular arc: degree (2, 9), one NURBS. */
    CHECK_STATUS(rmf_sweep_surface(spine, rmf, small, &surface), RMF_OK, "");
    if (surface) {
        RmfNurbsSurface view;
        CHECK_STATUS(rmf_surface_nurbs(surface, &view), RMF_OK, "");
        CHECK(view.degree_u == 2 && view.degree_v == 9, "profile surface of degree (2, 9)");
    }

    CHECK_STATUS(rmf_sweep_singularity_margin(spine, rmf, small, &m), RMF_OK, "");
    CHECK(m.margin > 0.5 && m.bound_margin > 0 && m.bound_margin <= m.margin, "a small profile is far from singular");
    CHECK_STATUS(rmf_sweep_singularity_margin(spine, rmf, big, &m), RMF_OK, "");
    printf("singularity margin (Corollary 7), arc of radius 2 on a helix whose radius of curvature is 1.16: %.4f at "
           "(u, v) = (%.3f, %.3f), bound %.4f\n",
           m.margin, m.u, m.v, m.bound_margin);
    CHECK(m.margin < 0 && m.bound_margin < 0, "a big profile crosses the curvature axis: singular");

    CHECK_STATUS(rmf_sweep_gaussian_curvature(spine, rmf, small, 0.5, 1.0, &k), RMF_OK, "");
    CHECK(k != 0 && isfinite(k), "Gaussian curvature of the profile surface");
    CHECK_STATUS(rmf_sweep_gaussian_curvature(spine, rmf, small, 1.5, 1.0, &k), RMF_ERROR_INVALID_INPUT, "u = 1.5");
    CHECK_STATUS(rmf_sweep_gaussian_curvature(spine, rmf, small, 0.5, -1.0, &k), RMF_ERROR_INVALID_INPUT, "v = -1");

    CHECK_STATUS(rmf_sweep_parabolic_points(spine, rmf, small, 9, NULL, 0, &count), RMF_OK, "");
    CHECK(count < 256, "parabolic points counted");
    CHECK_STATUS(rmf_sweep_parabolic_points(spine, rmf, small, 9, points, 256, &count), RMF_OK, "");
    CHECK_STATUS(rmf_sweep_parabolic_points(spine, rmf, small, 1, points, 256, &count), RMF_ERROR_INVALID_INPUT,
                 "v_samples");
    CHECK_STATUS(rmf_sweep_parabolic_points(spine, rmf, NULL, 9, points, 256, &count), RMF_ERROR_NULL_POINTER,
                 "profile");

    /* The parabolic lines (14) traced as curves: checked on the exported surface and spine
       with this suite's own evaluator, where the surface normal is perpendicular to the
       spine's principal normal. */
    if (surface) {
        RmfNurbsSurface view;
        RmfNurbsCurve spine_view;
        RmfParabolicCurvePoint *line = NULL;
        size_t n = 0, i, curves = 0;
        double worst = 0;
        CHECK_STATUS(rmf_sweep_parabolic_curves(spine, rmf, small, 1e-7, NULL, 0, &n), RMF_OK, "");
        CHECK(n > 2 && n < 100000, "parabolic line vertices counted");
        line = (RmfParabolicCurvePoint *)calloc(n, sizeof *line);
        CHECK_STATUS(rmf_surface_nurbs(surface, &view), RMF_OK, "");
        CHECK_STATUS(rmf_curve_nurbs(spine, &spine_view), RMF_OK, "");
        if (line && n > 1) {
            size_t short_count = 0;
            CHECK_STATUS(rmf_sweep_parabolic_curves(spine, rmf, small, 1e-7, line, n - 1, &short_count),
                         RMF_ERROR_BUFFER_TOO_SMALL, "capacity");
            CHECK(short_count == n, "a buffer too small still gets the count");
            CHECK_STATUS(rmf_sweep_parabolic_curves(spine, rmf, small, 1e-7, line, n, &n), RMF_OK, "");
            for (i = 0; i < n; i++) {
                RmfVec3 d[3][3], c[3], t, principal;
                size_t knot;
                int at_joint = 0;
                /* At a joint of the C1 spine the principal normal jumps, and so does the line:
                   a vertex there is one side's. */
                for (knot = 0; knot < spine_view.knot_count; knot++)
                    at_joint |= fabs(spine_view.knots[knot] - line[i].v) < 1e-12;
                ne_surface_derivatives(&view, line[i].u, line[i].v, d);
                ne_curve_derivatives(&spine_view, line[i].v, c);
                t = ne_unit(c[1]);
                principal = ne_unit(ne_sub(c[2], ne_scale(t, ne_dot(t, c[2]))));
                if (!at_joint) worst = fmax(worst, fabs(ne_dot(ne_unit(ne_cross(d[1][0], d[0][1])), principal)));
                CHECK(ne_dist(d[0][0], line[i].point) < 1e-12, "the vertex's point is the surface's");
                CHECK(i == 0 || line[i].curve == line[i - 1].curve || line[i].curve == line[i - 1].curve + 1,
                      "the vertices of a curve are consecutive");
                curves = line[i].curve + 1;
            }
            printf("parabolic lines (14) traced: %zu curves, %zu vertices, |n . principal normal| <= %.1e\n", curves,
                   n, worst);
            CHECK(worst < 1e-10, "the traced lines satisfy (14) on the exported surface");
        }
        free(line);
        CHECK_STATUS(rmf_sweep_parabolic_curves(spine, rmf, small, 0.0, NULL, 0, &n), RMF_ERROR_INVALID_INPUT,
                     "tolerance");
        CHECK_STATUS(rmf_sweep_parabolic_curves(spine, rmf, small, nan_value(), NULL, 0, &n),
                     RMF_ERROR_INVALID_INPUT, "tolerance");
        CHECK_STATUS(rmf_sweep_parabolic_curves(spine, NULL, small, 1e-7, NULL, 0, &n), RMF_ERROR_NULL_POINTER,
                     "frames");
    }

    CHECK_STATUS(rmf_ph_convex_initial_normal(spine, small, 1, &start, &margin), RMF_OK, "");
    CHECK(margin > 0 && fabs(ne_norm(start) - 1) < 1e-12, "Corollary 9 start for an elliptic patch");
    {
        /* A half circle turns by π: no start makes the patch convex. */
        const RmfVec3 poles[4] = {{1, 0, 0}, {1, 2, 0}, {-1, 2, 0}, {-1, 0, 0}};
        const double weights[4] = {1, 1.0 / 3, 1.0 / 3, 1}, knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
        RmfCurve *half = NULL;
        CHECK_STATUS(rmf_nurbs_curve_create(3, poles, weights, 4, knots, 8, &half), RMF_OK, "");
        CHECK_STATUS(rmf_ph_convex_initial_normal(spine, half, 1, &start, NULL), RMF_ERROR_NO_SOLUTION,
                     "Corollary 9");
        rmf_curve_free(half);
    }

    /* Offsets (Proposition 4): the offset of a circle is a circle, exactly. */
    CHECK_STATUS(rmf_profile_offset(small, 0.1, &offset), RMF_OK, "");
    if (offset) {
        RmfNurbsCurve view;
        int i;
        CHECK_STATUS(rmf_curve_nurbs(offset, &view), RMF_OK, "");
        CHECK(view.degree == 2, "the offset of an arc is an arc");
        for (i = 0; i <= 10; i++) {
            RmfVec3 d[3];
            ne_curve_derivatives(&view, i / 10.0, d);
            CHECK(fabs(ne_norm(d[0]) - 0.4) < 1e-14, "offset by 0.1 along (y', -x'): outwards");

        }
    }
    {
        const RmfVec3 poles[3] = {{2, 0, 0}, {2, 1, 0}, {0, 1, 0}};
        const double weights[3] = {1, sqrt(0.5), 1}, knots[6] = {0, 0, 0, 1, 1, 1};
        CHECK_STATUS(rmf_nurbs_curve_create(2, poles, weights, 3, knots, 6, &ellipse), RMF_OK, "");
    }
    if (ellipse) {
        /* The ellipse (2 cos t, sin t) has no rational offset: the exact offset of arcs within
           1e-5 of it, checked against the true offset (2 cos t, sin t) + d (cos t, 2 sin t)/|.|
           with this suite's evaluator and a dense closest-point scan. */
        RmfCurve *by_arcs = NULL, *arcs = NULL;
        double deviation = -1, worst = 0, d = 0.1;
        CHECK_STATUS(rmf_profile_offset_by_arcs(ellipse, d, 1e-5, &by_arcs, &arcs, &deviation), RMF_OK, "");
        if (by_arcs && arcs) {
            RmfNurbsCurve view, arc_view;
            int i, j;
            CHECK_STATUS(rmf_curve_nurbs(by_arcs, &view), RMF_OK, "");
            CHECK_STATUS(rmf_curve_nurbs(arcs, &arc_view), RMF_OK, "");
            CHECK(view.degree == 2 && arc_view.degree == 2, "arcs and their offset are rational quadratics");
            for (i = 0; i <= 200; i++) {
                RmfVec3 q[3];
                double best = INFINITY, t_best = 0, lo, hi;
                ne_curve_derivatives(&view, i / 200.0, q);
                for (j = 0; j <= 2000; j++) {
                    double t = PI / 2 * j / 2000.0;
                    if (ne_dist(ellipse_offset(t, d), q[0]) < best) best = ne_dist(ellipse_offset(t, d), q[0]), t_best = t;
                }
                /* Ternary search about the best sample (the distance is unimodal there). */
                lo = fmax(0, t_best - PI / 4000), hi = fmin(PI / 2, t_best + PI / 4000);
                for (j = 0; j < 200; j++) {
                    double a = lo + (hi - lo) / 3, b = hi - (hi - lo) / 3;
                    if (ne_dist(ellipse_offset(a, d), q[0]) < ne_dist(ellipse_offset(b, d), q[0]))
                        hi = b;
                    else
                        lo = a;
                }
                worst = fmax(worst, fmin(best, ne_dist(ellipse_offset(0.5 * (lo + hi), d), q[0])));
            }
            printf("offset of an ellipse through %zu arcs: measured %.1e, from the true offset %.1e (tolerance 1e-5)\n",
                   (arc_view.pole_count - 1) / 2, deviation, worst);
            CHECK(deviation > 0 && deviation <= 1e-5, "the measured deviation is within the tolerance");
            CHECK(worst <= 1e-5, "the offset of the arcs is within the tolerance of the true offset");
        }
        rmf_curve_free(by_arcs);
        rmf_curve_free(arcs);
    }
    {
        RmfCurve *c = untouched;
        CHECK_STATUS(rmf_profile_offset(ellipse, 0.1, &c), RMF_ERROR_NO_SOLUTION, "not rational");
        CHECK_STATUS(rmf_profile_offset_by_arcs(ellipse, 0.1, 0.0, &c, NULL, NULL), RMF_ERROR_INVALID_INPUT,
                     "tolerance");
        CHECK_STATUS(rmf_profile_offset_by_arcs(ellipse, 0.1, 1e-5, NULL, NULL, NULL), RMF_ERROR_NULL_POINTER,
                     "offset");
        CHECK_STATUS(rmf_profile_offset(small, nan_value(), &c), RMF_ERROR_INVALID_INPUT, "distance");
        CHECK_STATUS(rmf_profile_offset(NULL, 0.1, &c), RMF_ERROR_NULL_POINTER, "profile");
        CHECK(c == untouched, "a failing call leaves the out-pointer alone");
    }
    {
        /* A profile with no control points cannot even be made. */
        const double knots[2] = {0, 1};
        RmfCurve *empty = untouched;
        CHECK_STATUS(rmf_nurbs_curve_create(1, NULL, NULL, 0, knots, 2, &empty), RMF_ERROR_NULL_POINTER, "poles");
        CHECK_STATUS(rmf_nurbs_curve_create(1, (const RmfVec3 *)knots, NULL, 0, knots, 2, &empty),
                     RMF_ERROR_INVALID_INPUT, "pole_count");
        CHECK_STATUS(rmf_sweep_surface(spine, rmf, NULL, &surface), RMF_ERROR_NULL_POINTER, "profile");
        CHECK(empty == untouched, "nothing written");
    }
    rmf_surface_free(surface);
    rmf_curve_free(offset);
    rmf_curve_free(ellipse);
    rmf_frames_free(rmf);
    rmf_curve_free(spine);
    rmf_curve_free(small);
    rmf_curve_free(big);
}

/* A curve made from a callback: the approximations sample it as they sample the callback
   argument; entry points that need rational data refuse it, naming the argument. */
static void test_callback_curve(void) {
    double pitch = 0.5, d1 = -1, d2 = -2, lo = 0, hi = 0;
    RmfCurve *analytic = NULL, *from_handle = NULL, *from_pair = NULL, *untouched = (RmfCurve *)&pitch;
    RmfVec3 p = {0, 0, 0}, t = {0, 0, 0};
    RmfNurbsCurve view;
    size_t n1 = 0, n2 = 0;
    CHECK_STATUS(rmf_callback_curve_create(helix, &pitch, 0, 2 * PI, &analytic), RMF_OK, "");
    CHECK_STATUS(rmf_curve_domain(analytic, &lo, &hi), RMF_OK, "");
    CHECK(lo == 0 && hi == 2 * PI, "a callback curve has the domain given");
    CHECK_STATUS(rmf_curve_eval(analytic, 1.0, &p, &t), RMF_OK, "");
    CHECK(fabs(p.x - cos(1.0)) < 1e-15 && fabs(t.z - pitch) < 1e-15, "eval gives the callback's values");
    CHECK_STATUS(rmf_ph_spline_approximate(analytic, NULL, NULL, 0, 0, 1e-6, &from_handle, &d1), RMF_OK, "");
    CHECK_STATUS(rmf_ph_spline_approximate(NULL, helix, &pitch, 0, 2 * PI, 1e-6, &from_pair, &d2), RMF_OK, "");
    CHECK_STATUS(rmf_curve_segment_count(from_handle, &n1), RMF_OK, "");
    CHECK_STATUS(rmf_curve_segment_count(from_pair, &n2), RMF_OK, "");
    CHECK(n1 == n2 && d1 == d2, "a callback curve approximates as the callback pair does");
    CHECK_STATUS(rmf_curve_nurbs(analytic, &view), RMF_ERROR_INVALID_INPUT, "callback curve");
    CHECK_STATUS(rmf_curve_segment_count(analytic, &n1), RMF_ERROR_INVALID_INPUT, "callback curve");
    CHECK_STATUS(rmf_callback_curve_create(NULL, &pitch, 0, 1, &untouched), RMF_ERROR_NULL_POINTER, "callback");
    CHECK_STATUS(rmf_callback_curve_create(helix, &pitch, 1, 1, &untouched), RMF_ERROR_INVALID_INPUT, "t_min");
    CHECK_STATUS(rmf_callback_curve_create(helix, &pitch, 0, NAN, &untouched), RMF_ERROR_INVALID_INPUT, "t_max");
    CHECK(untouched == (RmfCurve *)&pitch, "out untouched on failure");
    rmf_curve_free(from_pair);
    rmf_curve_free(from_handle);
    rmf_curve_free(analytic);
}

/* The helix of `helix` with pitch 0.5, counting its calls. */
static size_t helix_calls = 0;
static void counted_helix(double t, void *user, RmfVec3 *point, RmfVec3 *tangent) {
    helix_calls++;
    helix(t, user, point, tangent);
}

/* rmf_ph_spline_approximate_with_options: the same spline as rmf_ph_spline_approximate, a
   report whose evaluations are the callback calls counted here, and caps that end in
   RMF_ERROR_NOT_CONVERGED without writing anything. */
static void test_approximate_with_options(void) {
    double pitch = 0.5, d = -1;
    RmfCurve *analytic = NULL, *plain = NULL, *capped = NULL, *untouched = (RmfCurve *)&pitch;
    RmfPhApproximationOptions options;
    RmfPhApproximationReport report = {sizeof(RmfPhApproximationReport), -1, 0, 0};
    size_t segments = 0;
    CHECK_STATUS(rmf_ph_approximation_options_init(&options), RMF_OK, "");
    CHECK(options.struct_size == sizeof options && options.tolerance == 0 && options.max_segments == 100000 &&
              options.max_evaluations == SIZE_MAX,
          "options_init writes the defaults");
    CHECK_STATUS(rmf_callback_curve_create(counted_helix, &pitch, 0, 2 * PI, &analytic), RMF_OK, "");
    CHECK_STATUS(rmf_ph_spline_approximate_with_options(analytic, &options, &capped, NULL), RMF_ERROR_INVALID_INPUT,
                 "tolerance");
    options.tolerance = 1e-6;
    helix_calls = 0;
    CHECK_STATUS(rmf_ph_spline_approximate_with_options(analytic, &options, &capped, &report), RMF_OK, "");
    CHECK(report.evaluations == helix_calls && helix_calls > 0, "the report counts every callback call");
    CHECK_STATUS(rmf_curve_segment_count(capped, &segments), RMF_OK, "");
    CHECK(report.segments == segments, "the report counts the segments");
    CHECK(report.max_distance > 0 && report.max_distance <= 1e-6, "the report's distance is within the tolerance");
    CHECK_STATUS(rmf_ph_spline_approximate(NULL, helix, &pitch, 0, 2 * PI, 1e-6, &plain, &d), RMF_OK, "");
    CHECK(d == report.max_distance, "the same spline as rmf_ph_spline_approximate");
    printf("rmf_ph_spline_approximate_with_options: helix to 1e-6 with %zu PH cubics, %zu callback calls\n",
           report.segments, report.evaluations);

    options.max_evaluations = report.evaluations - 1;
    CHECK_STATUS(rmf_ph_spline_approximate_with_options(analytic, &options, &untouched, &report), RMF_ERROR_NOT_CONVERGED,
                 "budget");
    options.max_evaluations = SIZE_MAX;
    options.max_segments = segments - 1;
    report.segments = 0;
    CHECK_STATUS(rmf_ph_spline_approximate_with_options(analytic, &options, &untouched, &report), RMF_ERROR_NOT_CONVERGED,
                 "max_segments");
    CHECK(untouched == (RmfCurve *)&pitch && report.segments == 0, "a failing call writes neither out nor report");
    options.max_segments = 0;
    CHECK_STATUS(rmf_ph_spline_approximate_with_options(analytic, &options, &untouched, NULL), RMF_ERROR_INVALID_INPUT,
                 "max_segments");
    options.max_segments = 100000;
    report.struct_size = 3;
    CHECK_STATUS(rmf_ph_spline_approximate_with_options(analytic, &options, &untouched, &report), RMF_ERROR_INVALID_INPUT,
                 "report->struct_size");
    options.tolerance = 4e-320;
    CHECK_STATUS(rmf_ph_spline_approximate_with_options(analytic, &options, &untouched, NULL), RMF_ERROR_INVALID_INPUT,
                 "below what f64 resolves");
    CHECK_STATUS(rmf_ph_spline_approximate_with_options(analytic, NULL, &untouched, NULL), RMF_ERROR_NULL_POINTER,
                 "options");
    CHECK_STATUS(rmf_ph_spline_approximate_with_options(NULL, &options, &untouched, NULL), RMF_ERROR_NULL_POINTER,
                 "curve");
    CHECK(untouched == (RmfCurve *)&pitch, "out untouched on failure");
    rmf_curve_free(plain);
    rmf_curve_free(capped);
    rmf_curve_free(analytic);
}

/* rmf_framed_spine: for every method, a spine within the tolerance of a NURBS cubic (measured
 * here with the suite's evaluator: 20 points per spine segment against the cubic, refined by
 * Newton), frames adapted to the spine; unknown methods, a zero tolerance and NULL
 * out-pointers refused with nothing written. */
static void test_framed_spine(void) {
    const RmfVec3 poles[4] = {{0, 0, 0}, {1, 1, 0}, {2, -1, 1}, {3, 0, 2}};
    const double knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
    const double tolerance = 1e-4;
    RmfCurve *cubic = NULL, *untouched_curve = (RmfCurve *)&knots;
    RmfFrames *untouched_frames = (RmfFrames *)&knots;
    RmfNurbsCurve input;
    uint32_t method;
    CHECK_STATUS(rmf_nurbs_curve_create(3, poles, NULL, 4, knots, 8, &cubic), RMF_OK, "");
    CHECK_STATUS(rmf_curve_nurbs(cubic, &input), RMF_OK, "");
    for (method = RMF_SPINE_PH_RMF; method <= RMF_SPINE_RRMF; method++) {
        RmfCurve *spine = NULL;
        RmfFrames *frames = NULL;
        RmfNurbsCurve view;
        double distance = -1, worst = 0, tangent_gap = 0, lo, hi;
        size_t k, segments = 0;
        CHECK_STATUS(rmf_framed_spine(cubic, method, tolerance, vec3(0, 0, 1), &spine, &frames,
                                      &distance),
                     RMF_OK, "");
        CHECK_STATUS(rmf_curve_nurbs(spine, &view), RMF_OK, "");
        CHECK_STATUS(rmf_curve_domain(spine, &lo, &hi), RMF_OK, "");
        CHECK_STATUS(rmf_curve_segment_count(spine, &segments), RMF_OK, "");
        for (k = 0; k <= 20 * segments; k++) {
            double t = lo + (hi - lo) * (double)k / (20.0 * (double)segments);
            RmfVec3 d[3], tangent, f2, f3;
            double e;
            ne_curve_derivatives(&view, t, d);
            e = distance_to(&input, d[0], 0, 1);
            if (e > worst) worst = e;
            CHECK_STATUS(rmf_frames_eval(frames, t, &tangent, &f2, &f3), RMF_OK, "");
            if (ne_dist(tangent, ne_unit(d[1])) > tangent_gap) tangent_gap = ne_dist(tangent, ne_unit(d[1]));
        }
        printf("framed spine, method %u: %zu segments, distance %.2e (library %.2e), frame "
               "tangent within %.1e\n",
               method, segments, worst, distance, tangent_gap);
        CHECK(distance >= 0 && distance <= tolerance, "the reported distance is within the tolerance");
        CHECK(worst <= 1.01 * tolerance, "the spine is within the tolerance of the curve");
        CHECK(tangent_gap < 1e-8, "the frames are adapted to the spine");
        rmf_frames_free(frames);
        rmf_curve_free(spine);
    }
    CHECK_STATUS(rmf_framed_spine(cubic, 9, tolerance, vec3(0, 0, 1), &untouched_curve,
                                  &untouched_frames, NULL),
                 RMF_ERROR_INVALID_INPUT, "method");
    CHECK_STATUS(rmf_framed_spine(cubic, RMF_SPINE_MOBIUS, 0, vec3(0, 0, 1), &untouched_curve,
                                  &untouched_frames, NULL),
                 RMF_ERROR_INVALID_INPUT, "tolerance");
    CHECK_STATUS(rmf_framed_spine(cubic, RMF_SPINE_PH_RMF, tolerance, vec3(0, 0, 1), NULL,
                                  &untouched_frames, NULL),
                 RMF_ERROR_NULL_POINTER, "spine_out");
    CHECK(untouched_curve == (RmfCurve *)&knots && untouched_frames == (RmfFrames *)&knots,
          "out-pointers untouched on failure");
    rmf_curve_free(cubic);
}

int main(void) {
    test_hermite();
    test_callback_curve();
    test_approximate_with_options();
    test_spline_hermite();
    test_approximation_order();
    test_spline_approximate();
    test_rational_rmf();
    test_closed_spine();
    test_profile_surface_analysis();
    test_framed_spine();
    return rmf_check_exit_code("abi_ph_cubic");
}
