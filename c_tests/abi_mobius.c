/*
 * C tests of the Möbius entry points: points, the normalized differential, exact images
 * of curves (checked pointwise from the exported NURBS with the suite's own evaluator),
 * and bad input. Runs under valgrind and the sanitizers.
 */
#include <math.h>
#include <stdlib.h>

#include "nurbs_eval.h"
#include "rmf_check.h"

static RmfInversion sphere(double x, double y, double z, double r) {
    RmfInversion m;
    memset(&m, 0, sizeof m);
    m.kind = RMF_INVERSION_SPHERE;
    m.center = vec3(x, y, z);
    m.radius = r;
    return m;
}

static RmfInversion plane(RmfVec3 point, RmfVec3 normal) {
    RmfInversion m;
    memset(&m, 0, sizeof m);
    m.kind = RMF_INVERSION_PLANE;
    m.center = point;
    m.normal = normal;
    return m;
}

static void test_points_and_vectors(void) {
    RmfInversion maps[2];
    RmfVec3 p = vec3(2, 0, 0), q, v;
    maps[0] = sphere(0, 0, 0, 2);
    maps[1] = plane(vec3(0, 0, 0), vec3(1, 0, 0));
    /* A point on the sphere is fixed by the inversion, then mirrored. */
    CHECK_STATUS(rmf_mobius_point(maps, 2, p, &q), RMF_OK, "");
    CHECK(ne_dist(q, vec3(-2, 0, 0)) < 1e-15, "inversion then reflection");
    p = vec3(4, 0, 0);
    CHECK_STATUS(rmf_mobius_point(maps, 1, p, &q), RMF_OK, "");
    CHECK(ne_dist(q, vec3(1, 0, 0)) < 1e-15, "r^2 / |y| on the axis");
    /* d*: radial vectors are reversed, tangential ones kept (eq. (12)). */
    CHECK_STATUS(rmf_mobius_vector(maps, 1, p, vec3(1, 0, 0), &v), RMF_OK, "");
    CHECK(ne_dist(v, vec3(-1, 0, 0)) < 1e-15, "radial vector reversed");
    CHECK_STATUS(rmf_mobius_vector(maps, 1, p, vec3(0, 3, 0), &v), RMF_OK, "");
    CHECK(ne_dist(v, vec3(0, 3, 0)) < 1e-15, "tangential vector kept, length kept");

    q = vec3(9, 9, 9);
    CHECK_STATUS(rmf_mobius_point(maps, 2, vec3(0, 0, 0), &q), RMF_ERROR_INVALID_INPUT, "infinity");
    CHECK_STATUS(rmf_mobius_point(NULL, 2, p, &q), RMF_ERROR_NULL_POINTER, "maps");
    CHECK_STATUS(rmf_mobius_point(maps, 0, p, &q), RMF_ERROR_INVALID_INPUT, "count");
    CHECK_STATUS(rmf_mobius_point(maps, 2, p, NULL), RMF_ERROR_NULL_POINTER, "image");
    CHECK_STATUS(rmf_mobius_point(maps, 2, vec3(nan_value(), 0, 0), &q), RMF_ERROR_INVALID_INPUT, "point");
    CHECK_STATUS(rmf_mobius_vector(maps, 2, p, vec3(0, nan_value(), 0), &q), RMF_ERROR_INVALID_INPUT, "vector");
    maps[0].radius = 0;
    CHECK_STATUS(rmf_mobius_point(maps, 2, p, &q), RMF_ERROR_INVALID_INPUT, "maps[0].radius");
    maps[0].radius = nan_value();
    CHECK_STATUS(rmf_mobius_point(maps, 2, p, &q), RMF_ERROR_INVALID_INPUT, "maps[0].radius");
    maps[0] = sphere(0, 0, 0, 2);
    maps[1].normal = vec3(0, 0, 0);
    CHECK_STATUS(rmf_mobius_point(maps, 2, p, &q), RMF_ERROR_INVALID_INPUT, "maps[1].normal");
    maps[1].kind = 7;
    CHECK_STATUS(rmf_mobius_point(maps, 2, p, &q), RMF_ERROR_INVALID_INPUT, "maps[1].kind");
    CHECK(q.x == 9 && q.y == 9, "image untouched on failure");
}

static void test_exact_curve_image(void) {
    static const RmfVec3 poles[5] = {{0, 0, 0}, {1, 2, 0.5}, {2, -1, 1}, {3, 1, -0.5}, {4, 0, 2}};
    static const double weights[5] = {1, 0.5, 2, 1, 0.7};
    static const double knots[9] = {0, 0, 0, 0, 0.6, 1, 1, 1, 1};
    RmfInversion maps[3];
    RmfCurve *curve = NULL, *image = NULL;
    RmfFrames *frames = NULL;
    RmfNurbsCurve source, view;
    double worst = 0;
    int i;
    maps[0] = sphere(1, 3, 2, 2.5);
    maps[1] = plane(vec3(0, 0.5, 0), vec3(1, 2, -1));
    maps[2] = sphere(-2, 0, 1.5, 1.8);
    CHECK_STATUS(rmf_nurbs_curve_create(3, poles, weights, 5, knots, 9, &curve), RMF_OK, "");
    if (!curve) return;
    CHECK_STATUS(rmf_mobius_curve(curve, maps, 3, &image), RMF_OK, "");
    if (!image) return;
    rmf_curve_nurbs(curve, &source);
    rmf_curve_nurbs(image, &view);
    CHECK(view.degree == 12, "two sphere inversions take a cubic to degree 12");
    for (i = 0; i <= 200; i++) {
        double t = i / 200.0;
        RmfVec3 x[3], y[3], expected;
        ne_curve_derivatives(&source, t, x);
        ne_curve_derivatives(&view, t, y);
        rmf_mobius_point(maps, 3, x[0], &expected);
        worst = fmax(worst, ne_dist(y[0], expected));
    }
    printf("exact Möbius image of a rational cubic (degree %u): max deviation from pointwise images %.2e\n",
           view.degree, worst);
    CHECK(worst < 1e-12, "the exported NURBS image is the pointwise image");

    /* A curve through an inversion centre has no bounded image. */
    {
        RmfVec3 x;
        RmfInversion through;
        RmfCurve *none = NULL;
        rmf_curve_eval(curve, 0.3, &x, NULL);
        through = sphere(x.x, x.y, x.z, 1.0);
        CHECK_STATUS(rmf_mobius_curve(curve, &through, 1, &none), RMF_ERROR_INVALID_INPUT, "inversion centre");
        CHECK(none == NULL, "out untouched on failure");
    }
    CHECK_STATUS(rmf_mobius_curve(NULL, maps, 3, &image), RMF_ERROR_NULL_POINTER, "curve");
    CHECK_STATUS(rmf_mobius_curve(curve, maps, 3, NULL), RMF_ERROR_NULL_POINTER, "out");
    /* Sampled frames have no exact image. */
    CHECK_STATUS(rmf_double_reflection_frames(curve, vec3(0, 0, 1), 100, &frames), RMF_OK, "");
    {
        RmfCurve *c = NULL;
        RmfFrames *f = NULL;
        CHECK_STATUS(rmf_mobius_frames(frames, maps, 3, &c, &f), RMF_ERROR_INVALID_INPUT, "rational");
        CHECK_STATUS(rmf_mobius_frames(frames, maps, 3, NULL, &f), RMF_ERROR_NULL_POINTER, "curve_out");
        CHECK_STATUS(rmf_mobius_frames(NULL, maps, 3, &c, &f), RMF_ERROR_NULL_POINTER, "frames");
        CHECK(c == NULL && f == NULL, "outputs untouched on failure");
    }
    rmf_frames_free(frames);
    rmf_curve_free(image);
    rmf_curve_free(curve);
}

/* The helix (cos t, sin t, 0.4 t) as a callback. */
static void helix(double t, void *user, RmfVec3 *point, RmfVec3 *tangent) {
    double pitch = *(const double *)user;
    *point = vec3(cos(t), sin(t), pitch * t);
    *tangent = vec3(-sin(t), cos(t), pitch);
}

static void silent(double t, void *user, RmfVec3 *point, RmfVec3 *tangent) {
    (void)t, (void)user, (void)point, (void)tangent;
}

/* Max RMF defect |f2'·f3| / |x'| and interpolation errors of a result, all from the
 * exported NURBS views evaluated by the suite's own code. */
static void check_rational_rmf(RmfCurve *curve, RmfFrames *frames, const RmfVec3 *points, const RmfVec3 *tangents,
                               size_t count, const char *what) {
    RmfCurve *f2_curve = NULL, *t_curve = NULL;
    RmfNurbsCurve x, f2, tn;
    double worst_defect = 0, worst_ortho = 0, worst_point = 0, worst_tangent = 0;
    size_t i;
    CHECK_STATUS(rmf_frames_vector_curve(frames, RMF_FRAME_F2, &f2_curve), RMF_OK, "");
    CHECK_STATUS(rmf_frames_vector_curve(frames, RMF_FRAME_TANGENT, &t_curve), RMF_OK, "");
    if (!f2_curve || !t_curve) return;
    rmf_curve_nurbs(curve, &x);
    rmf_curve_nurbs(f2_curve, &f2);
    rmf_curve_nurbs(t_curve, &tn);
    for (i = 0; i <= 2000; i++) {
        double t = x.knots[0] + (x.knots[x.knot_count - 1] - x.knots[0]) * i / 2000.0;
        RmfVec3 dx[3], df2[3], dt[3], f3, unit;
        double speed;
        ne_curve_derivatives(&x, t, dx);
        ne_curve_derivatives(&f2, t, df2);
        ne_curve_derivatives(&tn, t, dt);
        speed = ne_norm(dx[1]);
        unit = vec3(dx[1].x / speed, dx[1].y / speed, dx[1].z / speed);
        f3 = ne_cross(unit, df2[0]);
        worst_defect = fmax(worst_defect, fabs(ne_dot(df2[1], f3)) / speed);
        worst_ortho = fmax(worst_ortho, fmax(fabs(ne_dot(df2[0], unit)), fabs(ne_norm(df2[0]) - 1)));
        worst_tangent = fmax(worst_tangent, ne_dist(dt[0], unit));
    }
    for (i = 0; i < count; i++) {
        RmfVec3 d[3];
        double n = ne_norm(tangents[i]);
        ne_curve_derivatives(&x, (double)i, d);
        worst_point = fmax(worst_point, ne_dist(d[0], points[i]));
        worst_point = fmax(worst_point, ne_dist(vec3(d[1].x / ne_norm(d[1]), d[1].y / ne_norm(d[1]), d[1].z / ne_norm(d[1])),
                                                vec3(tangents[i].x / n, tangents[i].y / n, tangents[i].z / n)));
    }
    printf("%s: degree %u, %zu poles; max RMF defect %.2e /length, orthonormality %.2e, frame tangent %.2e, "
           "interpolation %.2e\n", what, x.degree, x.pole_count, worst_defect, worst_ortho, worst_tangent, worst_point);
    CHECK(worst_defect < 1e-9, "exact rational RMF: f2' . f3 = 0");
    CHECK(worst_ortho < 1e-12, "f2 is a unit normal vector");
    CHECK(worst_tangent < 1e-11, "the frames' tangent is the curve's");
    CHECK(worst_point < 1e-11, "points and tangents are interpolated");
    rmf_curve_free(f2_curve);
    rmf_curve_free(t_curve);
}

static void test_hermite_and_approximation(void) {
    RmfVec3 points[9], tangents[9], seed = vec3(0, 0, 1);
    RmfCurve *curve = NULL, *sentinel_curve = (RmfCurve *)(void *)&seed;
    RmfFrames *frames = NULL, *sentinel_frames = (RmfFrames *)(void *)&seed;
    double pitch = 0.4;
    int i;
    for (i = 0; i < 9; i++) helix(0.6 * i, &pitch, &points[i], &tangents[i]);
    CHECK_STATUS(rmf_mobius_rrmf_hermite(points, tangents, 9, seed, &curve, &frames), RMF_OK, "");
    if (curve && frames) check_rational_rmf(curve, frames, points, tangents, 9, "Möbius spline through 9 helix points");
    rmf_frames_free(frames);
    rmf_curve_free(curve);
    curve = NULL;
    frames = NULL;

    CHECK_STATUS(rmf_mobius_rrmf_approximate(NULL, helix, &pitch, 0.0, 6.0, 16, seed, &curve, &frames), RMF_OK, "");
    if (curve && frames) {
        RmfNurbsCurve view;
        double worst = 0;
        rmf_curve_nurbs(curve, &view);
        for (i = 0; i <= 16; i++) {
            RmfVec3 d[3], p, t;
            helix(6.0 * i / 16, &pitch, &p, &t);
            ne_curve_derivatives(&view, 6.0 * i / 16, d);
            worst = fmax(worst, ne_dist(d[0], p));
        }
        CHECK(worst < 1e-12, "joints at the callback's parameters");
    }
    rmf_frames_free(frames);
    rmf_curve_free(curve);

    /* Bad input: each failure names the argument and writes nothing. */
    curve = sentinel_curve;
    frames = sentinel_frames;
    CHECK_STATUS(rmf_mobius_rrmf_hermite(NULL, tangents, 9, seed, &curve, &frames), RMF_ERROR_NULL_POINTER, "points");
    CHECK_STATUS(rmf_mobius_rrmf_hermite(points, NULL, 9, seed, &curve, &frames), RMF_ERROR_NULL_POINTER, "tangents");
    CHECK_STATUS(rmf_mobius_rrmf_hermite(points, tangents, 9, seed, NULL, &frames), RMF_ERROR_NULL_POINTER, "curve");
    CHECK_STATUS(rmf_mobius_rrmf_hermite(points, tangents, 9, seed, &curve, NULL), RMF_ERROR_NULL_POINTER, "frames");
    CHECK_STATUS(rmf_mobius_rrmf_hermite(points, tangents, 1, seed, &curve, &frames), RMF_ERROR_INVALID_INPUT, "at least 2");
    CHECK_STATUS(rmf_mobius_rrmf_hermite(points, tangents, 0, seed, &curve, &frames), RMF_ERROR_INVALID_INPUT, "at least 2");
    points[3] = points[2];
    CHECK_STATUS(rmf_mobius_rrmf_hermite(points, tangents, 9, seed, &curve, &frames), RMF_ERROR_INVALID_INPUT,
                 "points[2] and points[3]");
    helix(1.8, &pitch, &points[3], &tangents[3]);
    tangents[4] = vec3(0, 0, 0);
    CHECK_STATUS(rmf_mobius_rrmf_hermite(points, tangents, 9, seed, &curve, &frames), RMF_ERROR_INVALID_INPUT, "tangents[4]");
    tangents[4] = vec3(nan_value(), 0, 1);
    CHECK_STATUS(rmf_mobius_rrmf_hermite(points, tangents, 9, seed, &curve, &frames), RMF_ERROR_INVALID_INPUT, "tangents[4]");
    helix(2.4, &pitch, &points[4], &tangents[4]);
    points[5].y = nan_value();
    CHECK_STATUS(rmf_mobius_rrmf_hermite(points, tangents, 9, seed, &curve, &frames), RMF_ERROR_INVALID_INPUT, "points[5]");
    helix(3.0, &pitch, &points[5], &tangents[5]);
    CHECK_STATUS(rmf_mobius_rrmf_hermite(points, tangents, 9, tangents[0], &curve, &frames), RMF_ERROR_INVALID_INPUT,
                 "initial_normal");
    CHECK_STATUS(rmf_mobius_rrmf_hermite(points, tangents, 9, vec3(0, 0, 0), &curve, &frames), RMF_ERROR_INVALID_INPUT,
                 "initial_normal");
    CHECK_STATUS(rmf_mobius_rrmf_approximate(NULL, NULL, NULL, 0, 1, 4, seed, &curve, &frames), RMF_ERROR_NULL_POINTER,
                 "callback");
    CHECK_STATUS(rmf_mobius_rrmf_approximate(NULL, helix, &pitch, 0, 6, 0, seed, &curve, &frames),
                 RMF_ERROR_INVALID_INPUT, "segments");
    CHECK_STATUS(rmf_mobius_rrmf_approximate(NULL, helix, &pitch, 1, 1, 4, seed, &curve, &frames),
                 RMF_ERROR_INVALID_INPUT, "t_min");
    CHECK_STATUS(rmf_mobius_rrmf_approximate(NULL, helix, &pitch, 0, nan_value(), 4, seed, &curve, &frames),
                 RMF_ERROR_INVALID_INPUT, "t_max");
    CHECK_STATUS(rmf_mobius_rrmf_approximate(NULL, silent, NULL, 0, 1, 4, seed, &curve, &frames),
                 RMF_ERROR_INVALID_INPUT, "callback");
    CHECK_STATUS(rmf_mobius_rrmf_approximate(NULL, helix, &pitch, 0, 6, 1, seed, &curve, &frames),
                 RMF_ERROR_NO_SOLUTION, "segment 0");
    CHECK(curve == sentinel_curve && frames == sentinel_frames, "outputs untouched on failure");
}

int main(void) {
    test_points_and_vectors();
    test_exact_curve_image();
    test_hermite_and_approximation();
    return rmf_check_exit_code("abi_mobius");
}
