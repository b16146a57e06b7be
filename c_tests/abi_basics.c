/*
 * C99 tests of the foundation ABI: every entry point with good input, NULL pointers,
 * NaN/Inf and malformed NURBS data. Each failure must return its status code with a
 * message naming the argument and leave out-pointers untouched; the whole program runs
 * under valgrind (no leaks, no invalid accesses). Geometry is checked against the suite's
 * own NURBS evaluator (nurbs_eval.c), not the library's.
 */
/* These tests call the deprecated wrappers on purpose (they keep working): no warning. */
#define RMF_DEPRECATED(note)
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "nurbs_eval.h"
#include "rmf_check.h"

/* A rational cubic with an interior double knot: two Bézier segments on [0, 0.3], [0.3, 1.2]. */
static const RmfVec3 CURVE_POLES[6] = {{0, 0, 0}, {1, 2, 0.5}, {2, -1, 1}, {3, 1, -0.5}, {4, 0, 2}, {5, 2, 1}};
static const double CURVE_WEIGHTS[6] = {1, 0.5, 2, 1, 0.7, 1};
static const double CURVE_KNOTS[10] = {0, 0, 0, 0, 0.3, 0.3, 1.2, 1.2, 1.2, 1.2};

static RmfCurve *make_curve(void) {
    RmfCurve *c = NULL;
    CHECK_STATUS(rmf_nurbs_curve_create(3, CURVE_POLES, CURVE_WEIGHTS, 6, CURVE_KNOTS, 10, &c), RMF_OK, "");
    return c;
}

/* Full cylinder x² + y² = 1, z ∈ [0, 2]: degree (2, 1), nine rational poles around. */
static RmfSurface *make_cylinder(void) {
    static const double ring[9][3] = {{1, 0, 1}, {1, 1, 0}, {0, 1, 1}, {-1, 1, 0}, {-1, 0, 1},
                                      {-1, -1, 0}, {0, -1, 1}, {1, -1, 0}, {1, 0, 1}};
    static const double knots_u[12] = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
    static const double knots_v[4] = {0, 0, 2, 2};
    RmfVec3 poles[18];
    double weights[18];
    RmfSurface *s = NULL;
    int i, j;
    for (i = 0; i < 9; i++)
        for (j = 0; j < 2; j++) {
            poles[i * 2 + j] = vec3(ring[i][0], ring[i][1], 2.0 * j);
            weights[i * 2 + j] = ring[i][2] == 1 ? 1.0 : sqrt(0.5);
        }
    CHECK_STATUS(rmf_nurbs_surface_create(2, 1, poles, weights, 9, 2, knots_u, 12, knots_v, 4, &s), RMF_OK, "");
    return s;
}

static void test_version_and_status_names(void) {
    unsigned major = 99, minor = 99, patch = 99;
    CHECK(rmf_version() != NULL, "rmf_version is not NULL");
    CHECK(sscanf(rmf_version(), "%u.%u.%u", &major, &minor, &patch) == 3, "version has three numbers");
    CHECK(major == RMF_VERSION_MAJOR && minor == RMF_VERSION_MINOR && patch == RMF_VERSION_PATCH,
          "header version macros agree with rmf_version()");
    CHECK(strcmp(rmf_status_name(RMF_ERROR_NULL_POINTER), "RMF_ERROR_NULL_POINTER") == 0, "status name");
    CHECK(strcmp(rmf_status_name(RMF_ERROR_INTERNAL), "RMF_ERROR_INTERNAL") == 0, "status name");
    CHECK(strcmp(rmf_status_name(RMF_ERROR_IO), "RMF_ERROR_IO") == 0, "status name");
    CHECK(strcmp(rmf_status_name(12345u), "RMF_UNKNOWN_STATUS") == 0, "unknown status");
    CHECK(RMF_OK == 0 && RMF_ERROR_NULL_POINTER == 1 && RMF_ERROR_INVALID_INPUT == 2 && RMF_ERROR_NO_SOLUTION == 3 &&
              RMF_ERROR_NOT_CONVERGED == 4 && RMF_ERROR_BUFFER_TOO_SMALL == 5 && RMF_ERROR_INTERNAL == 6 &&
              RMF_ERROR_IO == 7,
          "status values are fixed");
    CHECK(rmf_last_error() != NULL, "rmf_last_error is never NULL");
}

static void test_curve_good_input(void) {
    RmfCurve *c = make_curve();
    RmfNurbsCurve view;
    double t0 = -1, t1 = -1;
    size_t count = 0, i;
    if (!c) return;
    CHECK_STATUS(rmf_curve_domain(c, &t0, &t1), RMF_OK, "");
    CHECK(t0 == 0.0 && t1 == 1.2, "domain is the knot range");
    CHECK_STATUS(rmf_curve_nurbs(c, &view), RMF_OK, "");
    CHECK(view.degree == 3 && view.pole_count == 6 && view.knot_count == 10, "NURBS view sizes");
    for (i = 0; i < 6; i++)
        CHECK(view.poles[i].x == CURVE_POLES[i].x && view.weights[i] == CURVE_WEIGHTS[i], "NURBS view is the input");
    for (i = 0; i < 10; i++) CHECK(view.knots[i] == CURVE_KNOTS[i], "NURBS view knots are the input");
    /* The library's evaluation agrees with our own de Boor evaluation of its view. */
    for (i = 0; i <= 48; i++) {
        double t = 1.2 * (double)i / 48.0;
        RmfVec3 p, d, ref[3];
        CHECK_STATUS(rmf_curve_eval(c, t, &p, &d), RMF_OK, "");
        ne_curve_derivatives(&view, t, ref);
        CHECK(ne_dist(p, ref[0]) < 1e-12, "curve point agrees with de Boor");
        CHECK(ne_dist(d, ref[1]) < 1e-10 * (1.0 + ne_norm(ref[1])), "curve derivative agrees with de Boor");
    }
    {
        RmfVec3 p;
        CHECK_STATUS(rmf_curve_eval(c, 0.5, &p, NULL), RMF_OK, "");
    }
    /* Bézier segment views, evaluated by our own de Casteljau. */
    CHECK_STATUS(rmf_curve_segment_count(c, &count), RMF_OK, "");
    CHECK(count == 2, "two segments");
    for (i = 0; i < count; i++) {
        RmfBezierCurve seg;
        int k;
        CHECK_STATUS(rmf_curve_segment(c, i, &seg), RMF_OK, "");
        CHECK(seg.degree == 3, "segment degree");
        for (k = 0; k <= 10; k++) {
            double s = k / 10.0, t = seg.t_start + s * (seg.t_end - seg.t_start);
            RmfVec3 p, q = ne_bezier_point(&seg, s);
            rmf_curve_eval(c, t, &p, NULL);
            CHECK(ne_dist(p, q) < 1e-12, "segment view agrees with the curve");
        }
    }
    rmf_curve_free(c);
}

static void test_curve_copy_and_size_query(void) {
    RmfCurve *c = make_curve();
    uint32_t degree = 0;
    size_t poles_n = 0, knots_n = 0, i;
    RmfVec3 poles[6];
    double weights[6], knots[10], small_knots[3] = {-7, -7, -7};
    if (!c) return;
    CHECK_STATUS(rmf_curve_nurbs_copy(c, &degree, NULL, NULL, 0, NULL, 0, &poles_n, &knots_n), RMF_OK, "");
    CHECK(degree == 3 && poles_n == 6 && knots_n == 10, "size query");
    CHECK_STATUS(rmf_curve_nurbs_copy(c, &degree, poles, weights, 6, small_knots, 3, &poles_n, &knots_n),
                 RMF_ERROR_BUFFER_TOO_SMALL, "10 knots");
    CHECK(small_knots[0] == -7 && small_knots[2] == -7, "a too-small buffer is not written");
    CHECK(knots_n == 10, "the needed count is reported");
    CHECK_STATUS(rmf_curve_nurbs_copy(c, &degree, poles, weights, 6, knots, 10, &poles_n, &knots_n), RMF_OK, "");
    for (i = 0; i < 6; i++) CHECK(poles[i].z == CURVE_POLES[i].z && weights[i] == CURVE_WEIGHTS[i], "copied poles");
    for (i = 0; i < 10; i++) CHECK(knots[i] == CURVE_KNOTS[i], "copied knots");
    CHECK_STATUS(rmf_curve_nurbs_copy(c, &degree, NULL, weights, 6, knots, 10, &poles_n, &knots_n),
                 RMF_ERROR_NULL_POINTER, "poles");
    CHECK_STATUS(rmf_curve_nurbs_copy(c, NULL, poles, weights, 6, knots, 10, &poles_n, &knots_n),
                 RMF_ERROR_NULL_POINTER, "degree");
    CHECK_STATUS(rmf_curve_nurbs_copy(NULL, &degree, poles, weights, 6, knots, 10, &poles_n, &knots_n),
                 RMF_ERROR_NULL_POINTER, "curve");
    rmf_curve_free(c);
}

/* rmf_nurbs_curve_create with one thing wrong at a time. */
static void test_curve_bad_input(void) {
    static char storage;
    RmfCurve *const sentinel = (RmfCurve *)(void *)&storage;
    RmfCurve *out = sentinel;
    RmfVec3 poles[6];
    double weights[6], knots[10];
    memcpy(poles, CURVE_POLES, sizeof poles);
    memcpy(weights, CURVE_WEIGHTS, sizeof weights);
    memcpy(knots, CURVE_KNOTS, sizeof knots);

#define CREATE(deg, P, W, np, K, nk, expected, mention)                                             \
    do {                                                                                            \
        out = sentinel;                                                                             \
        CHECK_STATUS(rmf_nurbs_curve_create(deg, P, W, np, K, nk, &out), expected, mention);       \
        CHECK(out == sentinel, "out is untouched on failure");                                      \
    } while (0)

    CREATE(3, NULL, weights, 6, knots, 10, RMF_ERROR_NULL_POINTER, "poles");
    CREATE(3, poles, weights, 6, NULL, 10, RMF_ERROR_NULL_POINTER, "knots");
    CHECK_STATUS(rmf_nurbs_curve_create(3, poles, weights, 6, knots, 10, NULL), RMF_ERROR_NULL_POINTER, "out");
    CREATE(3, poles, weights, 6, knots, 9, RMF_ERROR_INVALID_INPUT, "knot_count");
    CREATE(3, poles, weights, 3, knots, 7, RMF_ERROR_INVALID_INPUT, "pole_count");
    CREATE(0, poles, weights, 6, knots, 7, RMF_ERROR_INVALID_INPUT, "degree");
    CREATE(65, poles, weights, 6, knots, 72, RMF_ERROR_INVALID_INPUT, "degree");
    CREATE(3, poles, weights, 0, knots, 4, RMF_ERROR_INVALID_INPUT, "pole_count");
    knots[5] = 0.2;
    CREATE(3, poles, weights, 6, knots, 10, RMF_ERROR_INVALID_INPUT, "knots");
    knots[5] = 0.3;
    knots[0] = -0.1;
    CREATE(3, poles, weights, 6, knots, 10, RMF_ERROR_INVALID_INPUT, "clamped");
    knots[0] = 0.0;
    knots[4] = nan_value();
    CREATE(3, poles, weights, 6, knots, 10, RMF_ERROR_INVALID_INPUT, "knots[4]");
    knots[4] = inf_value();
    CREATE(3, poles, weights, 6, knots, 10, RMF_ERROR_INVALID_INPUT, "knots");
    knots[4] = 0.3;
    {
        double all_zero[10] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
        CREATE(3, poles, weights, 6, all_zero, 10, RMF_ERROR_INVALID_INPUT, "empty");
    }
    {
        /* Interior multiplicity 4 > degree 3 (clamped, right count). */
        RmfVec3 p8[8];
        double k12[12] = {0, 0, 0, 0, 0.5, 0.5, 0.5, 0.5, 1, 1, 1, 1};
        memcpy(p8, CURVE_POLES, sizeof CURVE_POLES);
        p8[6] = vec3(6, 0, 0);
        p8[7] = vec3(7, 1, 0);
        CREATE(3, p8, NULL, 8, k12, 12, RMF_ERROR_INVALID_INPUT, "multiplicity");
    }
    poles[2].y = nan_value();
    CREATE(3, poles, weights, 6, knots, 10, RMF_ERROR_INVALID_INPUT, "poles[2]");
    poles[2].y = -inf_value();
    CREATE(3, poles, weights, 6, knots, 10, RMF_ERROR_INVALID_INPUT, "poles[2]");
    poles[2].y = -1;
    weights[3] = 0.0;
    CREATE(3, poles, weights, 6, knots, 10, RMF_ERROR_INVALID_INPUT, "weights[3]");
    weights[3] = -1.0;
    CREATE(3, poles, weights, 6, knots, 10, RMF_ERROR_INVALID_INPUT, "weights[3]");
    weights[3] = nan_value();
    CREATE(3, poles, weights, 6, knots, 10, RMF_ERROR_INVALID_INPUT, "weights[3]");
    weights[3] = 1.0;
    /* Weights may be NULL (all 1). */
    out = NULL;
    CHECK_STATUS(rmf_nurbs_curve_create(3, poles, NULL, 6, knots, 10, &out), RMF_OK, "");
    CHECK(out != NULL, "created with NULL weights");
    rmf_curve_free(out);
#undef CREATE
}

static void test_curve_accessors_reject_bad_input(void) {
    RmfCurve *c = make_curve();
    RmfVec3 p = vec3(7, 7, 7);
    RmfNurbsCurve view, before;
    RmfBezierCurve seg;
    double a = 5, b = 5;
    size_t n = 77;
    if (!c) return;
    CHECK_STATUS(rmf_curve_eval(NULL, 0.5, &p, NULL), RMF_ERROR_NULL_POINTER, "curve");
    CHECK_STATUS(rmf_curve_eval(c, 0.5, NULL, NULL), RMF_ERROR_NULL_POINTER, "point");
    CHECK_STATUS(rmf_curve_eval(c, nan_value(), &p, NULL), RMF_ERROR_INVALID_INPUT, "t");
    CHECK_STATUS(rmf_curve_eval(c, inf_value(), &p, NULL), RMF_ERROR_INVALID_INPUT, "t");
    CHECK_STATUS(rmf_curve_eval(c, 1.3, &p, NULL), RMF_ERROR_INVALID_INPUT, "outside the domain");
    CHECK_STATUS(rmf_curve_eval(c, -1e-3, &p, NULL), RMF_ERROR_INVALID_INPUT, "t");
    CHECK(p.x == 7 && p.y == 7 && p.z == 7, "point untouched on failure");
    CHECK_STATUS(rmf_curve_domain(NULL, &a, &b), RMF_ERROR_NULL_POINTER, "curve");
    CHECK_STATUS(rmf_curve_domain(c, NULL, &b), RMF_ERROR_NULL_POINTER, "t_min");
    CHECK_STATUS(rmf_curve_domain(c, &a, NULL), RMF_ERROR_NULL_POINTER, "t_max");
    CHECK(a == 5 && b == 5, "domain outputs untouched on failure");
    memset(&view, 0x5a, sizeof view);
    before = view;
    CHECK_STATUS(rmf_curve_nurbs(NULL, &view), RMF_ERROR_NULL_POINTER, "curve");
    CHECK_STATUS(rmf_curve_nurbs(c, NULL), RMF_ERROR_NULL_POINTER, "view");
    CHECK(memcmp(&view, &before, sizeof view) == 0, "view untouched on failure");
    CHECK_STATUS(rmf_curve_segment_count(NULL, &n), RMF_ERROR_NULL_POINTER, "curve");
    CHECK_STATUS(rmf_curve_segment_count(c, NULL), RMF_ERROR_NULL_POINTER, "count");
    CHECK(n == 77, "count untouched on failure");
    CHECK_STATUS(rmf_curve_segment(c, 2, &seg), RMF_ERROR_INVALID_INPUT, "index");
    CHECK_STATUS(rmf_curve_segment(c, (size_t)-1, &seg), RMF_ERROR_INVALID_INPUT, "index");
    CHECK_STATUS(rmf_curve_segment(c, 0, NULL), RMF_ERROR_NULL_POINTER, "view");
    CHECK_STATUS(rmf_curve_segment(NULL, 0, &seg), RMF_ERROR_NULL_POINTER, "curve");
    rmf_curve_free(c);
    rmf_curve_free(NULL);
}

static double max3(double a, double b, double c) { return a > b ? (a > c ? a : c) : (b > c ? b : c); }

static void test_frames(void) {
    RmfCurve *c = make_curve(), *reference = make_curve();
    RmfFrames *dr = NULL, *fr = NULL;
    static char storage;
    RmfFrames *const sentinel = (RmfFrames *)(void *)&storage;
    RmfFrames *out = sentinel;
    RmfVec3 t, f2, f3, seed = vec3(0, 0, 1);
    double lo = 0, hi = 0, worst_defect = 0, worst_ortho = 0;
    int i;
    if (!c || !reference) return;
    CHECK_STATUS(rmf_double_reflection_frames(c, seed, 2000, &dr), RMF_OK, "");
    CHECK_STATUS(rmf_frenet_frames(c, &fr), RMF_OK, "");
    /* The frames keep their own reference to the curve. */
    rmf_curve_free(c);
    c = NULL;
    CHECK_STATUS(rmf_frames_domain(dr, &lo, &hi), RMF_OK, "");
    CHECK(lo == 0.0 && hi == 1.2, "frames share the curve's domain");
    for (i = 1; i < 400; i++) {
        double h = 1e-6, s = 1.2 * i / 400.0;
        RmfVec3 a2, b2, dummy, d;
        CHECK_STATUS(rmf_frames_eval(dr, s, &t, &f2, &f3), RMF_OK, "");
        worst_ortho = max3(worst_ortho, fabs(ne_dot(t, f2)), fabs(ne_dot(f2, f3)));
        worst_ortho = max3(worst_ortho, fabs(ne_norm(f2) - 1), ne_dist(ne_cross(t, f2), f3));
        /* RMF defect f2'·f3 / |x'| by central differences (df2/dt then divide by speed). */
        rmf_frames_eval(dr, s - h, &dummy, &a2, &dummy);
        rmf_frames_eval(dr, s + h, &dummy, &b2, &dummy);
        d = ne_sub(b2, a2);
        {
            RmfVec3 p, x1;
            rmf_curve_eval(reference, s, &p, &x1);
            worst_defect = max3(worst_defect, fabs(ne_dot(d, f3)) / (2 * h) / ne_norm(x1), 0);
        }
        CHECK_STATUS(rmf_frames_eval(fr, s, &t, &f2, &f3), RMF_OK, "");
        worst_ortho = max3(worst_ortho, fabs(ne_dot(t, f2)), ne_dist(ne_cross(t, f2), f3));
    }
    printf("double-reflection frames (2000 samples): max orthonormality error %.2e, max RMF defect %.2e /length\n",
           worst_ortho, worst_defect);
    CHECK(worst_ortho < 1e-12, "frames are orthonormal");
    CHECK(worst_defect < 1e-4, "double reflection is rotation-minimizing up to its sampling accuracy");

    /* Bad input. */
    c = make_curve();
    CHECK_STATUS(rmf_double_reflection_frames(NULL, seed, 10, &out), RMF_ERROR_NULL_POINTER, "curve");
    CHECK_STATUS(rmf_double_reflection_frames(c, seed, 10, NULL), RMF_ERROR_NULL_POINTER, "out");
    CHECK_STATUS(rmf_double_reflection_frames(c, seed, 1, &out), RMF_ERROR_INVALID_INPUT, "sample_count");
    CHECK_STATUS(rmf_double_reflection_frames(c, seed, 0, &out), RMF_ERROR_INVALID_INPUT, "sample_count");
    CHECK_STATUS(rmf_double_reflection_frames(c, vec3(nan_value(), 0, 1), 10, &out), RMF_ERROR_INVALID_INPUT,
                 "initial_normal");
    CHECK_STATUS(rmf_double_reflection_frames(c, vec3(0, 0, 0), 10, &out), RMF_ERROR_INVALID_INPUT, "initial_normal");
    {
        /* The start tangent is along pole 1 − pole 0 = (1, 2, 0.5). */
        CHECK_STATUS(rmf_double_reflection_frames(c, vec3(2, 4, 1), 10, &out), RMF_ERROR_INVALID_INPUT,
                     "initial_normal");
    }
    CHECK(out == sentinel, "out untouched on failure");
    CHECK_STATUS(rmf_frenet_frames(NULL, &out), RMF_ERROR_NULL_POINTER, "curve");
    CHECK_STATUS(rmf_frenet_frames(c, NULL), RMF_ERROR_NULL_POINTER, "out");
    CHECK_STATUS(rmf_frames_eval(NULL, 0.5, &t, &f2, &f3), RMF_ERROR_NULL_POINTER, "frames");
    CHECK_STATUS(rmf_frames_eval(dr, 0.5, NULL, &f2, &f3), RMF_ERROR_NULL_POINTER, "tangent");
    CHECK_STATUS(rmf_frames_eval(dr, 0.5, &t, NULL, &f3), RMF_ERROR_NULL_POINTER, "f2");
    CHECK_STATUS(rmf_frames_eval(dr, 0.5, &t, &f2, NULL), RMF_ERROR_NULL_POINTER, "f3");
    CHECK_STATUS(rmf_frames_eval(dr, 2.0, &t, &f2, &f3), RMF_ERROR_INVALID_INPUT, "t");
    CHECK_STATUS(rmf_frames_eval(dr, nan_value(), &t, &f2, &f3), RMF_ERROR_INVALID_INPUT, "t");
    CHECK_STATUS(rmf_frames_domain(NULL, &lo, &hi), RMF_ERROR_NULL_POINTER, "frames");
    rmf_curve_free(c);
    {
        /* The Frenet frame of a straight line is undefined: a status, not NaN. */
        RmfVec3 line[2] = {{0, 0, 0}, {1, 1, 1}};
        double k[4] = {0, 0, 1, 1};
        RmfCurve *l = NULL;
        RmfFrames *lf = NULL;
        CHECK_STATUS(rmf_nurbs_curve_create(1, line, NULL, 2, k, 4, &l), RMF_OK, "");
        CHECK_STATUS(rmf_frenet_frames(l, &lf), RMF_OK, "");
        f2 = vec3(3, 3, 3);
        CHECK_STATUS(rmf_frames_eval(lf, 0.5, &t, &f2, &f3), RMF_ERROR_INVALID_INPUT, "curvature");
        CHECK(f2.x == 3, "f2 untouched on failure");
        rmf_frames_free(lf);
        rmf_curve_free(l);
    }
    {
        /* Sampled frames have no rational form: no vector curves, no rational sweep. */
        uint32_t kind = 99;
        RmfCurve *vector_curve = NULL;
        RmfSurface *surface = NULL;
        CHECK_STATUS(rmf_frames_kind(dr, &kind), RMF_OK, "");
        CHECK(kind == RMF_FRAMES_DOUBLE_REFLECTION, "double-reflection frames say so");
        CHECK_STATUS(rmf_frames_kind(fr, &kind), RMF_OK, "");
        CHECK(kind == RMF_FRAMES_FRENET, "Frenet frames say so");
        CHECK_STATUS(rmf_frames_kind(NULL, &kind), RMF_ERROR_NULL_POINTER, "frames");
        CHECK_STATUS(rmf_frames_kind(dr, NULL), RMF_ERROR_NULL_POINTER, "kind");
        CHECK_STATUS(rmf_frames_vector_curve(dr, RMF_FRAME_F2, &vector_curve), RMF_ERROR_INVALID_INPUT, "rational");
        CHECK_STATUS(rmf_frames_vector_curve(dr, 7u, &vector_curve), RMF_ERROR_INVALID_INPUT, "which");
        CHECK_STATUS(rmf_frames_vector_curve(NULL, RMF_FRAME_F2, &vector_curve), RMF_ERROR_NULL_POINTER, "frames");
        CHECK_STATUS(rmf_frames_vector_curve(dr, RMF_FRAME_F2, NULL), RMF_ERROR_NULL_POINTER, "out");
        CHECK(vector_curve == NULL, "out untouched on failure");
        CHECK_STATUS(rmf_sweep_surface(reference, dr, reference, &surface), RMF_ERROR_INVALID_INPUT, "rational");
        CHECK_STATUS(rmf_sweep_surface(NULL, dr, reference, &surface), RMF_ERROR_NULL_POINTER, "spine");
        CHECK_STATUS(rmf_sweep_surface(reference, NULL, reference, &surface), RMF_ERROR_NULL_POINTER, "frames");
        CHECK_STATUS(rmf_sweep_surface(reference, dr, NULL, &surface), RMF_ERROR_NULL_POINTER, "profile");
        CHECK_STATUS(rmf_sweep_surface(reference, dr, reference, NULL), RMF_ERROR_NULL_POINTER, "out");
        CHECK(surface == NULL, "out untouched on failure");
    }
    rmf_frames_free(dr);
    rmf_frames_free(fr);
    rmf_frames_free(NULL);
    rmf_curve_free(reference);
}

static void test_surface_good_input(void) {
    RmfSurface *s = make_cylinder();
    RmfNurbsSurface view;
    double u0, u1, v0, v1;
    size_t cu = 0, cv = 0, np = 0, nt = 0, i, j;
    RmfVec3 *points;
    uint32_t *triangles;
    if (!s) return;
    CHECK_STATUS(rmf_surface_domain(s, &u0, &u1, &v0, &v1), RMF_OK, "");
    CHECK(u0 == 0 && u1 == 1 && v0 == 0 && v1 == 2, "surface domain");
    CHECK_STATUS(rmf_surface_nurbs(s, &view), RMF_OK, "");
    CHECK(view.degree_u == 2 && view.degree_v == 1 && view.pole_count_u == 9 && view.pole_count_v == 2 &&
              view.knot_count_u == 12 && view.knot_count_v == 4,
          "surface NURBS view sizes");
    for (i = 0; i <= 20; i++)
        for (j = 0; j <= 4; j++) {
            double u = i / 20.0, v = 2.0 * j / 4.0;
            RmfVec3 p, du, dv, d[3][3];
            CHECK_STATUS(rmf_surface_eval(s, u, v, &p, &du, &dv), RMF_OK, "");
            ne_surface_derivatives(&view, u, v, d);
            CHECK(ne_dist(p, d[0][0]) < 1e-12, "surface point agrees with de Boor");
            CHECK(ne_dist(du, d[1][0]) < 1e-10 && ne_dist(dv, d[0][1]) < 1e-10, "surface partials agree");
            CHECK(fabs(p.x * p.x + p.y * p.y - 1) < 1e-14, "on the cylinder");
        }
    CHECK_STATUS(rmf_surface_patch_count(s, &cu, &cv), RMF_OK, "");
    CHECK(cu == 4 && cv == 1, "4 × 1 patches");
    {
        RmfBezierPatch patch;
        CHECK_STATUS(rmf_surface_patch(s, 3, 0, &patch), RMF_OK, "");
        CHECK(patch.degree_u == 2 && patch.degree_v == 1 && patch.u_start == 0.75 && patch.u_end == 1.0,
              "patch view");
        CHECK(fabs(patch.poles[0].x - 0.0) < 1e-15 && fabs(patch.poles[0].y + 1.0) < 1e-15, "patch corner pole");
        CHECK_STATUS(rmf_surface_patch(s, 4, 0, &patch), RMF_ERROR_INVALID_INPUT, "patch");
        CHECK_STATUS(rmf_surface_patch(s, 0, 1, &patch), RMF_ERROR_INVALID_INPUT, "patch");
    }
    /* Tessellation: size query, too small, then the real thing. */
    CHECK_STATUS(rmf_surface_tessellate(s, 5, 3, NULL, 0, NULL, 0, &np, &nt), RMF_OK, "");
    CHECK(np == 21 * 4 && nt == 2 * 20 * 3, "tessellation sizes");
    points = (RmfVec3 *)malloc(np * sizeof *points);
    triangles = (uint32_t *)malloc(3 * nt * sizeof *triangles);
    if (!points || !triangles) abort();
    CHECK_STATUS(rmf_surface_tessellate(s, 5, 3, points, np - 1, triangles, nt, &np, &nt), RMF_ERROR_BUFFER_TOO_SMALL,
                 "points");
    CHECK_STATUS(rmf_surface_tessellate(s, 5, 3, points, np, triangles, nt, &np, &nt), RMF_OK, "");
    for (i = 0; i < 3 * nt; i++) CHECK(triangles[i] < np, "triangle indices are in range");
    for (i = 0; i < np; i++) {
        /* Point (i, j) of the 21 × 4 grid is at u = i/20, v = 2 j/3. */
        RmfVec3 d[3][3];
        ne_surface_derivatives(&view, (double)(i / 4) / 20.0, 2.0 * (double)(i % 4) / 3.0, d);
        CHECK(ne_dist(points[i], d[0][0]) < 1e-12, "tessellation point agrees with de Boor");
    }
    free(points);
    free(triangles);
    rmf_surface_free(s);
}

static void test_surface_bad_input(void) {
    static const double ku[4] = {0, 0, 1, 1}, kv[4] = {0, 0, 1, 1}, bad[4] = {0, 0, 1, 0.5};
    RmfVec3 poles[4] = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 1}};
    double weights[4] = {1, 1, 1, 1};
    static char storage;
    RmfSurface *const sentinel = (RmfSurface *)(void *)&storage;
    RmfSurface *out = sentinel, *s = NULL;
    RmfVec3 p = vec3(9, 9, 9);
    size_t np = 5, nt = 5;
    double a, b, c, d;
    CHECK_STATUS(rmf_nurbs_surface_create(1, 1, NULL, weights, 2, 2, ku, 4, kv, 4, &out), RMF_ERROR_NULL_POINTER, "poles");
    CHECK_STATUS(rmf_nurbs_surface_create(1, 1, poles, weights, 2, 2, NULL, 4, kv, 4, &out), RMF_ERROR_NULL_POINTER, "knots_u");
    CHECK_STATUS(rmf_nurbs_surface_create(1, 1, poles, weights, 2, 2, ku, 4, NULL, 4, &out), RMF_ERROR_NULL_POINTER, "knots_v");
    CHECK_STATUS(rmf_nurbs_surface_create(1, 1, poles, weights, 2, 2, ku, 4, kv, 4, NULL), RMF_ERROR_NULL_POINTER, "out");
    CHECK_STATUS(rmf_nurbs_surface_create(1, 1, poles, weights, 2, 2, ku, 3, kv, 4, &out), RMF_ERROR_INVALID_INPUT, "knot_count_u");
    CHECK_STATUS(rmf_nurbs_surface_create(1, 1, poles, weights, 2, 2, ku, 4, bad, 4, &out), RMF_ERROR_INVALID_INPUT, "knots_v");
    CHECK_STATUS(rmf_nurbs_surface_create(1, 1, poles, weights, SIZE_MAX, 2, ku, 4, kv, 4, &out), RMF_ERROR_INVALID_INPUT, "pole_count_u");
    CHECK_STATUS(rmf_nurbs_surface_create(2, 1, poles, weights, 2, 2, ku, 4, kv, 4, &out), RMF_ERROR_INVALID_INPUT, "pole_count_u");
    weights[1] = -2;
    CHECK_STATUS(rmf_nurbs_surface_create(1, 1, poles, weights, 2, 2, ku, 4, kv, 4, &out), RMF_ERROR_INVALID_INPUT, "weights[1]");
    weights[1] = 1;
    poles[3].z = nan_value();
    CHECK_STATUS(rmf_nurbs_surface_create(1, 1, poles, weights, 2, 2, ku, 4, kv, 4, &out), RMF_ERROR_INVALID_INPUT, "poles[3]");
    poles[3].z = 1;
    CHECK(out == sentinel, "out untouched on failure");
    CHECK_STATUS(rmf_nurbs_surface_create(1, 1, poles, NULL, 2, 2, ku, 4, kv, 4, &s), RMF_OK, "");
    if (!s) return;
    CHECK_STATUS(rmf_surface_eval(NULL, 0.5, 0.5, &p, NULL, NULL), RMF_ERROR_NULL_POINTER, "surface");
    CHECK_STATUS(rmf_surface_eval(s, 0.5, 0.5, NULL, NULL, NULL), RMF_ERROR_NULL_POINTER, "point");
    CHECK_STATUS(rmf_surface_eval(s, nan_value(), 0.5, &p, NULL, NULL), RMF_ERROR_INVALID_INPUT, "u");
    CHECK_STATUS(rmf_surface_eval(s, 0.5, 1.5, &p, NULL, NULL), RMF_ERROR_INVALID_INPUT, "v");
    CHECK(p.x == 9, "point untouched on failure");
    CHECK_STATUS(rmf_surface_domain(s, &a, &b, NULL, &d), RMF_ERROR_NULL_POINTER, "v_min");
    CHECK_STATUS(rmf_surface_domain(NULL, &a, &b, &c, &d), RMF_ERROR_NULL_POINTER, "surface");
    CHECK_STATUS(rmf_surface_tessellate(s, 0, 3, NULL, 0, NULL, 0, &np, &nt), RMF_ERROR_INVALID_INPUT, "u_steps");
    CHECK_STATUS(rmf_surface_tessellate(s, 4294967295u, 4294967295u, NULL, 0, NULL, 0, &np, &nt),
                 RMF_ERROR_INVALID_INPUT, "exceeds");
    CHECK(np == 5 && nt == 5, "counts untouched on invalid input");
    CHECK_STATUS(rmf_surface_tessellate(s, 2, 2, NULL, 9, NULL, 8, &np, &nt), RMF_ERROR_NULL_POINTER, "points");
    CHECK_STATUS(rmf_surface_tessellate(s, 2, 2, NULL, 0, NULL, 0, NULL, &nt), RMF_ERROR_NULL_POINTER, "point_count");
    CHECK_STATUS(rmf_surface_tessellate(NULL, 2, 2, NULL, 0, NULL, 0, &np, &nt), RMF_ERROR_NULL_POINTER, "surface");
    {
        RmfNurbsSurface view;
        size_t n[4];
        uint32_t du, dv;
        CHECK_STATUS(rmf_surface_nurbs(NULL, &view), RMF_ERROR_NULL_POINTER, "surface");
        CHECK_STATUS(rmf_surface_nurbs(s, NULL), RMF_ERROR_NULL_POINTER, "view");
        CHECK_STATUS(rmf_surface_nurbs_copy(s, &du, &dv, NULL, NULL, 0, NULL, 0, NULL, 0, &n[0], &n[1], &n[2], &n[3]),
                     RMF_OK, "");
        CHECK(du == 1 && dv == 1 && n[0] == 2 && n[1] == 2 && n[2] == 4 && n[3] == 4, "surface size query");
        {
            RmfVec3 cp[4];
            double cw[4], cku[4], ckv[3];
            CHECK_STATUS(rmf_surface_nurbs_copy(s, &du, &dv, cp, cw, 4, cku, 4, ckv, 3, &n[0], &n[1], &n[2], &n[3]),
                         RMF_ERROR_BUFFER_TOO_SMALL, "knots");
            CHECK_STATUS(rmf_surface_nurbs_copy(s, &du, &dv, cp, cw, 4, cku, 4, NULL, 4, &n[0], &n[1], &n[2], &n[3]),
                         RMF_ERROR_NULL_POINTER, "knots_v");
        }
        {
            RmfVec3 cp[4];
            double cw[4], cku[4], ckv[4];
            CHECK_STATUS(rmf_surface_nurbs_copy(s, &du, &dv, cp, cw, 4, cku, 4, ckv, 4, &n[0], &n[1], &n[2], &n[3]),
                         RMF_OK, "");
            CHECK(cp[3].z == 1 && cw[2] == 1 && cku[2] == 1 && ckv[1] == 0, "surface NURBS copy");
        }
    }
    rmf_surface_free(s);
    rmf_surface_free(NULL);
}

/* The entry points with a struct instead of 11 and 14 arguments (0.2): rmf_nurbs_surface_create_from
 * makes the surface of rmf_nurbs_surface_create, rmf_surface_nurbs_copy_into copies what
 * rmf_surface_nurbs_copy copies; NULL structs and wrong struct sizes are refused with a
 * message naming the argument, and nothing is written. */
static void test_surface_structs(void) {
    static const double ring[9][3] = {{1, 0, 1}, {1, 1, 0}, {0, 1, 1}, {-1, 1, 0}, {-1, 0, 1},
                                      {-1, -1, 0}, {0, -1, 1}, {1, -1, 0}, {1, 0, 1}};
    static const double knots_u[12] = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
    static const double knots_v[4] = {0, 0, 2, 2}, bad_v[4] = {0, 0, 2, 1};
    static char storage;
    RmfSurface *const sentinel = (RmfSurface *)(void *)&storage;
    RmfVec3 poles[18], cp[18], old_cp[18];
    double weights[18], cw[18], cku[12], ckv[4], old_cw[18], old_cku[12], old_ckv[4];
    RmfNurbsSurfaceData data;
    RmfNurbsSurfaceBuffers buffers;
    RmfNurbsSurface copy, untouched_copy;
    RmfSurface *s = NULL, *old = NULL, *out = sentinel;
    size_t n[4], i;
    uint32_t du = 0, dv = 0;
    int u, v;
    for (i = 0; i < 9; i++)
        for (u = 0; u < 2; u++) {
            poles[i * 2 + u] = vec3(ring[i][0], ring[i][1], 2.0 * u);
            weights[i * 2 + u] = ring[i][2] == 1 ? 1.0 : sqrt(0.5);
        }
    memset(&data, 0, sizeof data);
    data.struct_size = sizeof data;
    data.degree_u = 2;
    data.degree_v = 1;
    data.pole_count_u = 9;
    data.pole_count_v = 2;
    data.poles = poles;
    data.weights = weights;
    data.knot_count_u = 12;
    data.knots_u = knots_u;
    data.knot_count_v = 4;
    data.knots_v = knots_v;
    CHECK_STATUS(rmf_nurbs_surface_create_from(&data, &s), RMF_OK, "");
    CHECK_STATUS(rmf_nurbs_surface_create(2, 1, poles, weights, 9, 2, knots_u, 12, knots_v, 4, &old), RMF_OK, "");
    if (!s || !old) return;
    for (u = 0; u <= 8; u++)
        for (v = 0; v <= 4; v++) {
            RmfVec3 a, b;
            CHECK_STATUS(rmf_surface_eval(s, u / 8.0, v / 2.0, &a, NULL, NULL), RMF_OK, "");
            CHECK_STATUS(rmf_surface_eval(old, u / 8.0, v / 2.0, &b, NULL, NULL), RMF_OK, "");
            CHECK(a.x == b.x && a.y == b.y && a.z == b.z, "the surface of rmf_nurbs_surface_create");
        }

    /* Size query, too small, then the copy, against rmf_surface_nurbs_copy. */
    memset(&buffers, 0, sizeof buffers);
    buffers.struct_size = sizeof buffers;
    CHECK_STATUS(rmf_surface_nurbs_copy_into(s, &buffers, &copy), RMF_OK, "");
    CHECK(copy.degree_u == 2 && copy.degree_v == 1 && copy.pole_count_u == 9 && copy.pole_count_v == 2 &&
              copy.knot_count_u == 12 && copy.knot_count_v == 4 && copy.poles == NULL && copy.knots_v == NULL,
          "size query: degrees and counts, no pointers");
    buffers.poles = cp;
    buffers.weights = cw;
    buffers.pole_capacity = 18;
    buffers.knots_u = cku;
    buffers.knot_capacity_u = 12;
    buffers.knots_v = ckv;
    buffers.knot_capacity_v = 3;
    memset(&copy, 0, sizeof copy);
    CHECK_STATUS(rmf_surface_nurbs_copy_into(s, &buffers, &copy), RMF_ERROR_BUFFER_TOO_SMALL, "knots");
    CHECK(copy.knot_count_v == 4 && copy.knots_v == NULL, "too small: the counts say what is needed");
    buffers.knot_capacity_v = 4;
    CHECK_STATUS(rmf_surface_nurbs_copy_into(s, &buffers, &copy), RMF_OK, "");
    CHECK(copy.poles == cp && copy.weights == cw && copy.knots_u == cku && copy.knots_v == ckv,
          "the copy points at the caller's buffers");
    CHECK_STATUS(rmf_surface_nurbs_copy(old, &du, &dv, old_cp, old_cw, 18, old_cku, 12, old_ckv, 4, &n[0], &n[1], &n[2],
                                        &n[3]),
                 RMF_OK, "");
    CHECK(du == copy.degree_u && dv == copy.degree_v && n[0] == copy.pole_count_u && n[1] == copy.pole_count_v &&
              n[2] == copy.knot_count_u && n[3] == copy.knot_count_v,
          "the degrees and counts of rmf_surface_nurbs_copy");
    for (i = 0; i < 18; i++)
        CHECK(cp[i].x == old_cp[i].x && cp[i].y == old_cp[i].y && cp[i].z == old_cp[i].z && cw[i] == old_cw[i],
              "the poles and weights of rmf_surface_nurbs_copy");
    for (i = 0; i < 12; i++) CHECK(cku[i] == old_cku[i] && cku[i] == knots_u[i], "the u knots");
    for (i = 0; i < 4; i++) CHECK(ckv[i] == old_ckv[i] && ckv[i] == knots_v[i], "the v knots");

    /* Bad input. */
    memset(&untouched_copy, 0x5e, sizeof untouched_copy);
    copy = untouched_copy;
    CHECK_STATUS(rmf_nurbs_surface_create_from(NULL, &out), RMF_ERROR_NULL_POINTER, "data");
    CHECK_STATUS(rmf_nurbs_surface_create_from(&data, NULL), RMF_ERROR_NULL_POINTER, "out");
    data.struct_size = sizeof data - 8;
    CHECK_STATUS(rmf_nurbs_surface_create_from(&data, &out), RMF_ERROR_INVALID_INPUT, "data->struct_size");
    data.struct_size = 0;
    CHECK_STATUS(rmf_nurbs_surface_create_from(&data, &out), RMF_ERROR_INVALID_INPUT, "data->struct_size");
    data.struct_size = sizeof data;
    data.knots_v = NULL;
    CHECK_STATUS(rmf_nurbs_surface_create_from(&data, &out), RMF_ERROR_NULL_POINTER, "data->knots_v");
    data.knots_v = bad_v;
    CHECK_STATUS(rmf_nurbs_surface_create_from(&data, &out), RMF_ERROR_INVALID_INPUT, "data: knots_v");
    data.knots_v = knots_v;
    data.knot_count_u = 11;
    CHECK_STATUS(rmf_nurbs_surface_create_from(&data, &out), RMF_ERROR_INVALID_INPUT, "data: knot_count_u");
    CHECK(out == sentinel, "out untouched on failure");
    CHECK_STATUS(rmf_surface_nurbs_copy_into(s, NULL, &copy), RMF_ERROR_NULL_POINTER, "buffers");
    CHECK_STATUS(rmf_surface_nurbs_copy_into(NULL, &buffers, &copy), RMF_ERROR_NULL_POINTER, "surface");
    CHECK_STATUS(rmf_surface_nurbs_copy_into(s, &buffers, NULL), RMF_ERROR_NULL_POINTER, "copy");
    buffers.struct_size = sizeof buffers + 8;
    CHECK_STATUS(rmf_surface_nurbs_copy_into(s, &buffers, &copy), RMF_ERROR_INVALID_INPUT, "buffers->struct_size");
    CHECK(strstr(rmf_last_error(), "sizeof(RmfNurbsSurfaceBuffers)") != NULL, "the message says how to set it");
    buffers.struct_size = sizeof buffers;
    buffers.knots_u = NULL;
    CHECK_STATUS(rmf_surface_nurbs_copy_into(s, &buffers, &copy), RMF_ERROR_NULL_POINTER, "buffers->knots_u");
    CHECK(memcmp(&copy, &untouched_copy, sizeof copy) == 0, "copy untouched on failure");
    rmf_surface_free(s);
    rmf_surface_free(old);
}

/* The primitive curves, evaluated by the suite's own NURBS evaluator: a circle at its
 * radius in its plane, an arc through its three points, a polygon through its corners, an
 * obround at its radius from its segment; bad arguments refused naming them, out untouched. */
static double worst_on_curve(RmfCurve *c, double (*off)(RmfVec3), int samples) {
    RmfNurbsCurve view;
    double worst = 0.0, lo, hi;
    int k;
    CHECK_STATUS(rmf_curve_nurbs(c, &view), RMF_OK, "");
    lo = view.knots[0];
    hi = view.knots[view.knot_count - 1];
    for (k = 0; k <= samples; k++) {
        RmfVec3 d[3];
        ne_curve_derivatives(&view, lo + (hi - lo) * k / samples, d);
        worst = fmax(worst, fabs(off(d[0])));
    }
    return worst;
}

/* Circle: centre (1, 2, 3), radius 2.5, in the plane x = 1 (axes y and z). */
static double off_circle(RmfVec3 p) {
    return fabs(ne_norm(ne_sub(p, vec3(1, 2, 3))) - 2.5) + fabs(p.x - 1.0);
}

/* Arc through (10, 0, 0), (0, 10, 0), (-6, -8, 0): the circle of radius 10 about 0 in z = 0. */
static double off_arc(RmfVec3 p) { return fabs(ne_norm(p) - 10.0) + fabs(p.z); }

/* Obround: radius 1.5 from the segment (±3, 0, 5). */
static double off_obround(RmfVec3 p) {
    double x = fmin(3.0, fmax(-3.0, p.x));
    return fabs(ne_norm(ne_sub(p, vec3(x, 0, 5))) - 1.5) + fabs(p.z - 5.0);
}

static void test_primitive_curves(void) {
    static char storage;
    RmfCurve *const sentinel = (RmfCurve *)(void *)&storage;
    RmfCurve *c = NULL, *out = sentinel;
    RmfNurbsCurve view;
    RmfVec3 corners[4] = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}}, d[3];

    CHECK_STATUS(rmf_curve_circle(vec3(1, 2, 3), vec3(0, 1, 0), vec3(0, 0, 1), 2.5, &c), RMF_OK, "");
    CHECK(worst_on_curve(c, off_circle, 400) < 1e-13, "the circle is at its radius in its plane");
    rmf_curve_free(c);
    CHECK_STATUS(rmf_curve_arc(vec3(10, 0, 0), vec3(0, 10, 0), vec3(-6, -8, 0), &c), RMF_OK, "");
    CHECK(worst_on_curve(c, off_arc, 400) < 1e-13, "the arc is on its circle");
    CHECK_STATUS(rmf_curve_nurbs(c, &view), RMF_OK, "");
    ne_curve_derivatives(&view, view.knots[view.knot_count - 1], d);
    CHECK(ne_dist(d[0], vec3(-6, -8, 0)) < 1e-14, "the arc ends at its end point");
    rmf_curve_free(c);
    CHECK_STATUS(rmf_curve_polygon(corners, 4, &c), RMF_OK, "");
    CHECK_STATUS(rmf_curve_nurbs(c, &view), RMF_OK, "");
    CHECK(view.degree == 1 && view.pole_count == 5, "a polygon of 4 corners has 5 poles");
    ne_curve_derivatives(&view, 2.5, d);
    CHECK(ne_dist(d[0], vec3(1, 1, 0)) < 1e-15, "the polygon's third side");
    rmf_curve_free(c);
    CHECK_STATUS(rmf_curve_polyline(corners, 2, &c), RMF_OK, "");
    rmf_curve_free(c);
    CHECK_STATUS(rmf_curve_obround(vec3(0, 0, 5), vec3(2, 0, 0), vec3(0, 1, 0), 6.0, 1.5, &c), RMF_OK, "");
    CHECK(worst_on_curve(c, off_obround, 600) < 1e-13, "the obround is at its radius from its segment");
    rmf_curve_free(c);

    CHECK_STATUS(rmf_curve_circle(vec3(nan_value(), 0, 0), vec3(1, 0, 0), vec3(0, 1, 0), 1, &out),
                 RMF_ERROR_INVALID_INPUT, "centre");
    CHECK_STATUS(rmf_curve_circle(vec3(0, 0, 0), vec3(1, 0, 0), vec3(2, 0, 0), 1, &out),
                 RMF_ERROR_INVALID_INPUT, "y_axis");
    CHECK_STATUS(rmf_curve_circle(vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0), -1, &out),
                 RMF_ERROR_INVALID_INPUT, "radius");
    CHECK_STATUS(rmf_curve_circle(vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0), 1, NULL),
                 RMF_ERROR_NULL_POINTER, "out");
    CHECK_STATUS(rmf_curve_arc(vec3(0, 0, 0), vec3(1, 0, 0), vec3(2, 0, 0), &out),
                 RMF_ERROR_INVALID_INPUT, "collinear");
    CHECK_STATUS(rmf_curve_polyline(NULL, 3, &out), RMF_ERROR_NULL_POINTER, "points");
    CHECK_STATUS(rmf_curve_polyline(corners, 1, &out), RMF_ERROR_INVALID_INPUT, "points");
    CHECK_STATUS(rmf_curve_polygon(corners, 2, &out), RMF_ERROR_INVALID_INPUT, "corners");
    CHECK_STATUS(rmf_curve_obround(vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0), -1, 1, &out),
                 RMF_ERROR_INVALID_INPUT, "length");
    CHECK(out == sentinel, "failing calls leave out untouched");
}

int main(void) {
    test_version_and_status_names();
    test_curve_good_input();
    test_curve_copy_and_size_query();
    test_curve_bad_input();
    test_curve_accessors_reject_bad_input();
    test_frames();
    test_surface_good_input();
    test_surface_bad_input();
    test_surface_structs();
    test_primitive_curves();
    return rmf_check_exit_code("abi_basics");
}
