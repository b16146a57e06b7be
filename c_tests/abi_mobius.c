/*
 * C tests of the Möbius entry points: points, the normalized differential, exact images
 * of curves (checked pointwise from the exported NURBS with the suite's own evaluator),
 * and bad input. Runs under valgrind and the sanitizers.
 */
#include <math.h>
#include <stdlib.h>

#include "nurbs_eval.h"
#include "rmf_check.h"

static double nan_value(void) { return strtod("nan", NULL); }

static RmfVec3 vec3(double x, double y, double z) {
    RmfVec3 v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}

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

int main(void) {
    test_points_and_vectors();
    test_exact_curve_image();
    return rmf_check_exit_code("abi_mobius");
}
