/*
 * C99 tests of the cone spline ABI: every entry point with good input, NULL pointers, NaN,
 * and the bad inputs of issue 8 (rulings parallel with opposite orientation, coincident
 * elements, inconsistent side vectors, non-developable input with its measured K, regions
 * containing every possible vertex, bad counts and tolerances). Each failure returns its
 * status with a message naming the argument and leaves out-pointers untouched; the
 * program runs under valgrind (no leaks). Geometry is checked with the suite's own NURBS
 * evaluator.
 */
/* These tests call the deprecated wrappers on purpose (they keep working): no warning. */
#define RMF_DEPRECATED(note)
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "nurbs_eval.h"
#include "rmf_check.h"

#define vec3(x, y, z) ((RmfVec3){(x), (y), (z)})


/* The twisted cubic (t, t², t³). */
static void cubic(double t, void *user, RmfVec3 *point, RmfVec3 *tangent) {
    (void)user;
    *point = vec3(t, t * t, t * t * t);
    *tangent = vec3(1, 2 * t, 3 * t * t);
}

/* The element of the tangent surface of the twisted cubic at t, distance v along e. */
static RmfConeElement cubic_element(double t, double v) {
    RmfVec3 p, d1, d2 = vec3(0, 2, 6 * t), e, n;
    RmfConeElement el;
    cubic(t, NULL, &p, &d1);
    e = ne_unit(d1);
    n = ne_unit(ne_add(d2, ne_scale(e, -ne_dot(d2, e)))); /* principal normal */
    el.point = ne_add(p, ne_scale(e, v));
    el.ruling = e;
    el.side = v > 0 ? n : ne_scale(n, -1);
    return el;
}

/* (t, t², t⁴): zero torsion at t = 0, an inflection generator of its tangent surface. */
static void quartic(double t, void *user, RmfVec3 *point, RmfVec3 *tangent) {
    (void)user;
    *point = vec3(t, t * t, t * t * t * t);
    *tangent = vec3(1, 2 * t, 4 * t * t * t);
}

static RmfConeSpline *sentinel_spline(void) { return (RmfConeSpline *)(uintptr_t)0x5e5e; }

static void test_hermite_surface_and_pieces(void) {
    RmfConeElement els[4];
    RmfConeSpline *spline = NULL, *bent = NULL, *flat = NULL, *offset = NULL;
    RmfSurface *surface = NULL;
    RmfCurve *edge = NULL;
    RmfNurbsSurface view;
    RmfNurbsCurve edge_view;
    RmfConePiece piece;
    RmfBox box;
    size_t count = 0, i;
    double t0 = 0, t1 = 0, worst_k = 0;
    for (i = 0; i < 4; i++) els[i] = cubic_element(0.3 + 0.2 * (double)i, 2.5);
    CHECK_STATUS(rmf_cone_spline_hermite(els, 4, RMF_CONE_RULE_MIN_VERTEX_DISTANCE, 0, NULL, &spline), RMF_OK, "");
    if (!spline) return;
    CHECK_STATUS(rmf_cone_spline_piece_count(spline, &count), RMF_OK, "");
    CHECK(count == 6, "three cone pairs");
    for (i = 0; i < count; i++) {
        CHECK_STATUS(rmf_cone_spline_piece(spline, i, &piece), RMF_OK, "");
        CHECK(piece.kind == RMF_CONE_PIECE_CONE && piece.pair_case == RMF_CONE_CASE_GENERAL, "general cone pairs");
        CHECK(piece.has_vertex == 1 && piece.half_angle > 0 && piece.half_angle < 1.5708, "a cone with a vertex");
        CHECK(piece.segment_angle > 0 && piece.segment_angle < 0.5, "short segments");
        CHECK(fabs(piece.developed_angle - piece.segment_angle * sin(piece.half_angle)) < 1e-15, "phi sin alpha");
        CHECK(piece.first_patch == i && piece.patch_count == 1, "one patch per piece");
    }
    CHECK_STATUS(rmf_cone_spline_piece(spline, 6, &piece), RMF_ERROR_INVALID_INPUT, "index");
    CHECK_STATUS(rmf_cone_spline_surface(spline, -0.3, 0.3, &surface), RMF_OK, "");
    CHECK_STATUS(rmf_surface_nurbs(surface, &view), RMF_OK, "");
    CHECK(view.degree_u == 1 && view.degree_v == 2 && view.pole_count_u == 2 && view.pole_count_v == 13,
          "one NURBS of degree (1, 2)");
    for (i = 0; i <= 60; i++) {
        RmfVec3 d[3][3];
        ne_surface_derivatives(&view, -0.3 + 0.6 * (double)(i % 7) / 6.0, 6.0 * (double)i / 60.0, d);
        worst_k = fmax(worst_k, fabs(ne_gaussian_curvature(d)));
    }
    CHECK(worst_k < 1e-9, "developable: K = 0 on the NURBS view");
    CHECK_STATUS(rmf_cone_spline_boundary(spline, 0.3, &edge), RMF_OK, "");
    CHECK_STATUS(rmf_curve_nurbs(edge, &edge_view), RMF_OK, "");
    CHECK(edge_view.degree == 2 && edge_view.pole_count == 13, "the boundary is an arc spline");
    box.min = vec3(-5, -5, -5);
    box.max = vec3(5, 5, 5);
    CHECK_STATUS(rmf_cone_spline_bounds_in_box(spline, &box, &t0, &t1), RMF_OK, "");
    CHECK(t0 < t1, "the box holds a strip");
    {
        RmfSurface *strip = NULL;
        CHECK_STATUS(rmf_cone_spline_surface(spline, t0, t1, &strip), RMF_OK, "");
        rmf_surface_free(strip);
    }
    /* A box of ±1e308 (its width overflows): finite, ordered bounds (was t_min = +inf). */
    box.min = vec3(-1e308, -1e308, -1e308);
    box.max = vec3(1e308, 1e308, 1e308);
    CHECK_STATUS(rmf_cone_spline_bounds_in_box(spline, &box, &t0, &t1), RMF_OK, "");
    CHECK(isfinite(t0) && isfinite(t1) && t0 < t1, "finite bounds in a box of 1e308");
    CHECK_STATUS(rmf_cone_spline_bend(spline, 0.5, &bent), RMF_OK, "");
    CHECK_STATUS(rmf_cone_spline_develop(spline, &flat), RMF_OK, "");
    CHECK_STATUS(rmf_cone_spline_offset(spline, 0.1, &offset), RMF_OK, "");
    /* Failing calls on a good spline leave the out-pointers as they were. */
    {
        RmfConeSpline *untouched = sentinel_spline();
        RmfSurface *no_surface = (RmfSurface *)(uintptr_t)0x5e5e;
        double err = -1;
        CHECK_STATUS(rmf_cone_spline_bend(spline, 1.5, &untouched), RMF_ERROR_INVALID_INPUT, "s = 1.5");
        CHECK_STATUS(rmf_cone_spline_bend(spline, nan(""), &untouched), RMF_ERROR_INVALID_INPUT, "s = NaN");
        CHECK_STATUS(rmf_cone_spline_offset(spline, INFINITY, &untouched), RMF_ERROR_INVALID_INPUT, "d = inf");
        CHECK(untouched == sentinel_spline(), "out untouched");
        CHECK_STATUS(rmf_cone_spline_surface(spline, 0.3, 0.3, &no_surface), RMF_ERROR_INVALID_INPUT, "t_min");
        CHECK_STATUS(rmf_cone_spline_surface(spline, -9.0, 9.0, &no_surface), RMF_ERROR_INVALID_INPUT, "vertex");
        CHECK(no_surface == (RmfSurface *)(uintptr_t)0x5e5e, "surface untouched");
        CHECK_STATUS(rmf_cone_spline_fit_error(spline, &err), RMF_ERROR_INVALID_INPUT, "approximation");
        CHECK(err == -1, "max_error untouched");
        CHECK_STATUS(rmf_cone_spline_surface(NULL, 0, 1, &no_surface), RMF_ERROR_NULL_POINTER, "spline");
        CHECK_STATUS(rmf_cone_spline_surface(spline, 0, 1, NULL), RMF_ERROR_NULL_POINTER, "out");
        CHECK_STATUS(rmf_cone_spline_boundary(spline, nan(""), &edge), RMF_ERROR_INVALID_INPUT, "t = NaN");
        CHECK_STATUS(rmf_cone_spline_bounds_in_box(spline, NULL, &t0, &t1), RMF_ERROR_NULL_POINTER, "region");
        box.min = vec3(50, 50, 50);
        box.max = vec3(51, 51, 51);
        CHECK_STATUS(rmf_cone_spline_bounds_in_box(spline, &box, &t0, &t1), RMF_ERROR_NO_SOLUTION, "misses");
        box.max = vec3(49, 51, 51);
        CHECK_STATUS(rmf_cone_spline_bounds_in_box(spline, &box, &t0, &t1), RMF_ERROR_INVALID_INPUT, "region.min");
        CHECK_STATUS(rmf_cone_spline_piece_count(NULL, &count), RMF_ERROR_NULL_POINTER, "spline");
    }
    rmf_curve_free(edge);
    rmf_surface_free(surface);
    rmf_cone_spline_free(offset);
    rmf_cone_spline_free(flat);
    rmf_cone_spline_free(bent);
    rmf_cone_spline_free(spline);
    rmf_cone_spline_free(NULL);
}

static void test_hermite_bad_input(void) {
    RmfConeElement els[2];
    RmfConeSpline *out = sentinel_spline();
    RmfBox box;
    els[0] = cubic_element(0.4, 2.5);
    els[1] = cubic_element(0.6, 2.5);
    CHECK_STATUS(rmf_cone_spline_hermite(NULL, 2, 0, 0, NULL, &out), RMF_ERROR_NULL_POINTER, "elements");
    CHECK_STATUS(rmf_cone_spline_hermite(els, 2, 0, 0, NULL, NULL), RMF_ERROR_NULL_POINTER, "out");
    CHECK_STATUS(rmf_cone_spline_hermite(els, 1, 0, 0, NULL, &out), RMF_ERROR_INVALID_INPUT, "count = 1");
    CHECK_STATUS(rmf_cone_spline_hermite(els, 2, 99, 0, NULL, &out), RMF_ERROR_INVALID_INPUT, "rule = 99");
    CHECK_STATUS(rmf_cone_spline_hermite(els, 2, RMF_CONE_RULE_GIVEN, nan(""), NULL, &out), RMF_ERROR_INVALID_INPUT,
                 "parameter");
    els[1].point.y = nan("");
    CHECK_STATUS(rmf_cone_spline_hermite(els, 2, 0, 0, NULL, &out), RMF_ERROR_INVALID_INPUT, "elements[1].point");
    els[1] = cubic_element(0.6, 2.5);
    els[0].side = ne_add(els[0].side, ne_scale(els[0].ruling, 0.2));
    CHECK_STATUS(rmf_cone_spline_hermite(els, 2, 0, 0, NULL, &out), RMF_ERROR_INVALID_INPUT, "elements[0].side");
    els[0] = cubic_element(0.4, 2.5);
    els[0].ruling = vec3(0, 0, 0);
    CHECK_STATUS(rmf_cone_spline_hermite(els, 2, 0, 0, NULL, &out), RMF_ERROR_INVALID_INPUT, "elements[0].ruling");
    /* Parallel rulings with opposite orientation. */
    els[0].point = vec3(0, 0, 0), els[0].ruling = vec3(0, 0, 1), els[0].side = vec3(1, 0, 0);
    els[1].point = vec3(1, 0, 0), els[1].ruling = vec3(0, 0, -1), els[1].side = vec3(1, 0, 0);
    CHECK_STATUS(rmf_cone_spline_hermite(els, 2, 0, 0, NULL, &out), RMF_ERROR_INVALID_INPUT, "opposite orientation");
    /* Coincident elements. */
    els[1] = els[0];
    els[1].point.z = 3;
    CHECK_STATUS(rmf_cone_spline_hermite(els, 2, 0, 0, NULL, &out), RMF_ERROR_INVALID_INPUT, "coincident");
    /* Inconsistent side vectors: the normals point to opposite sides. */
    els[1].point = vec3(1, 0, 0), els[1].side = vec3(-1, 0.2, 0);
    CHECK_STATUS(rmf_cone_spline_hermite(els, 2, 0, 0, NULL, &out), RMF_ERROR_INVALID_INPUT, "side vectors");
    /* Intersecting rulings: every possible vertex is their common point; a box around it. */
    els[0].point = vec3(1, 0, 1), els[0].ruling = vec3(1, 0, 1), els[0].side = vec3(0, 1, 0);
    els[1].point = vec3(0, 1, 1), els[1].ruling = vec3(0, 1, 1), els[1].side = vec3(-1, 0, 0);
    box.min = vec3(-2, -2, -2);
    box.max = vec3(2, 2, 2);
    CHECK_STATUS(rmf_cone_spline_hermite(els, 2, 0, 0, &box, &out), RMF_ERROR_NO_SOLUTION, "every possible vertex");
    CHECK_STATUS(rmf_cone_spline_hermite(els, 2, RMF_CONE_RULE_CYLINDER_FIRST, 0, NULL, &out), RMF_ERROR_NO_SOLUTION,
                 "cylinder");
    box.min = vec3(0.5, -2, -2);
    CHECK_STATUS(rmf_cone_spline_hermite(els, 2, 0, 0, &box, &out), RMF_ERROR_INVALID_INPUT, "outside the region");
    CHECK(out == sentinel_spline(), "no failing call wrote out");
    /* The same rulings without a region: a cone pair with the common vertex. */
    out = NULL;
    CHECK_STATUS(rmf_cone_spline_hermite(els, 2, 0, 0, NULL, &out), RMF_OK, "");
    {
        RmfConePiece piece;
        CHECK_STATUS(rmf_cone_spline_piece(out, 0, &piece), RMF_OK, "");
        CHECK(piece.pair_case == RMF_CONE_CASE_CONE && ne_norm(piece.vertex) < 1e-12, "cone case, vertex 0");
    }
    rmf_cone_spline_free(out);
}

static void test_approximations(void) {
    RmfConeSpline *spline = NULL, *untouched = sentinel_spline();
    double err = -1, params[64];
    size_t n = 0;
    CHECK_STATUS(rmf_cone_spline_approximate(NULL, cubic, NULL, 0.2, 1.2, 0.5, 1.0, 1e-3,
                                             RMF_CONE_RULE_MIN_VERTEX_DISTANCE, 1000, &spline, &err),
                 RMF_OK, "");
    CHECK(err > 0 && err <= 1e-3, "within the tolerance");
    CHECK_STATUS(rmf_cone_spline_fit_parameters(spline, RMF_CONE_FIT_ELEMENTS, NULL, 0, &n), RMF_OK, "");
    CHECK(n >= 3 && n <= 64, "a few elements");
    CHECK_STATUS(rmf_cone_spline_fit_parameters(spline, RMF_CONE_FIT_ELEMENTS, params, 1, &n),
                 RMF_ERROR_BUFFER_TOO_SMALL, "need");
    CHECK_STATUS(rmf_cone_spline_fit_parameters(spline, RMF_CONE_FIT_ELEMENTS, params, 64, &n), RMF_OK, "");
    CHECK(params[0] == 0.2 && params[n - 1] == 1.2, "elements span the domain");
    CHECK_STATUS(rmf_cone_spline_fit_parameters(spline, 7, params, 64, &n), RMF_ERROR_INVALID_INPUT, "which");
    CHECK_STATUS(rmf_cone_spline_fit_error(spline, &err), RMF_OK, "");
    rmf_cone_spline_free(spline);

    /* The inflection generator at t = 0 is found and kept as a junction. */
    CHECK_STATUS(rmf_cone_spline_approximate(NULL, quartic, NULL, -1.0, 1.0, 0.3, 0.8, 1e-3,
                                             RMF_CONE_RULE_MIN_VERTEX_DISTANCE, 1000, &spline, &err),
                 RMF_OK, "");
    CHECK_STATUS(rmf_cone_spline_fit_parameters(spline, RMF_CONE_FIT_INFLECTIONS, params, 64, &n), RMF_OK, "");
    CHECK(n == 1 && fabs(params[0]) < 1e-9, "one inflection generator, at t = 0");
    {
        double inflection = params[0];
        size_t k, found = 0;
        CHECK_STATUS(rmf_cone_spline_fit_parameters(spline, RMF_CONE_FIT_ELEMENTS, params, 64, &n), RMF_OK, "");
        for (k = 0; k < n; k++) found += params[k] == inflection;
        CHECK(found == 1, "the inflection generator is an element (a junction)");
    }
    rmf_cone_spline_free(spline);

    CHECK_STATUS(rmf_cone_spline_approximate(NULL, cubic, NULL, 0.2, 1.2, 0.5, 1.0, 0.0, 0, 1000, &untouched, NULL),
                 RMF_ERROR_INVALID_INPUT, "tolerance");
    CHECK_STATUS(rmf_cone_spline_approximate(NULL, cubic, NULL, 0.2, 1.2, -0.5, 1.0, 1e-3, 0, 1000, &untouched, NULL),
                 RMF_ERROR_INVALID_INPUT, "contains 0");
    CHECK_STATUS(rmf_cone_spline_approximate(NULL, NULL, NULL, 0.2, 1.2, 0.5, 1.0, 1e-3, 0, 1000, &untouched, NULL),
                 RMF_ERROR_NULL_POINTER, "curve and callback");
    CHECK_STATUS(rmf_cone_spline_approximate(NULL, cubic, NULL, 1.2, 0.2, 0.5, 1.0, 1e-3, 0, 1000, &untouched, NULL),
                 RMF_ERROR_INVALID_INPUT, "t_min");
    CHECK_STATUS(rmf_cone_spline_approximate(NULL, cubic, NULL, 0.2, 1.2, 0.5, 1.0, 1e-3, RMF_CONE_RULE_GIVEN, 1000,
                                             &untouched, NULL),
                 RMF_ERROR_INVALID_INPUT, "RMF_CONE_RULE_GIVEN");
    CHECK_STATUS(rmf_cone_spline_approximate(NULL, cubic, NULL, 0.2, 1.2, 0.5, 1.0, 1e-9, 0, 6, &untouched, NULL),
                 RMF_ERROR_NOT_CONVERGED, "max_pieces = 6");
    CHECK_STATUS(rmf_cone_spline_approximate(NULL, cubic, NULL, 0.2, 1.2, 0.5, 1.0, 1e-3, 0, 1, &untouched, NULL),
                 RMF_ERROR_INVALID_INPUT, "max_pieces");
    CHECK(untouched == sentinel_spline(), "failing approximations write nothing");

    /* A saddle z = xy as a degree (1, 1) surface is ruled but not developable. */
    {
        const RmfVec3 poles[4] = {{-1, -1, 1}, {-1, 1, -1}, {1, -1, -1}, {1, 1, 1}};
        const double knots[4] = {0, 0, 1, 1};
        RmfSurface *saddle = NULL;
        CHECK_STATUS(rmf_nurbs_surface_create(1, 1, poles, NULL, 2, 2, knots, 4, knots, 4, &saddle), RMF_OK, "");
        CHECK_STATUS(rmf_cone_spline_approximate_ruled(saddle, 1e-3, 0, 100, &untouched, NULL),
                     RMF_ERROR_INVALID_INPUT, "not developable");
        CHECK(strstr(rmf_last_error(), "|K|") != NULL, "the message reports the measured curvature");
        CHECK_STATUS(rmf_cone_spline_approximate_ruled(NULL, 1e-3, 0, 100, &untouched, NULL), RMF_ERROR_NULL_POINTER,
                     "surface");
        rmf_surface_free(saddle);
    }
    /* The dual form: a quadratic B-spline of planes through the origin (a cone). */
    {
        const double planes[12] = {0, 1, 0, -0.5, 0, 1, 1, -0.5, 0, 0, 1, -0.5};
        const double knots[6] = {0, 0, 0, 1, 1, 1}, bad_knots[6] = {0, 0, 0, 1, 0.5, 1};
        RmfBox box;
        box.min = vec3(-3, -3, 1);
        box.max = vec3(3, 3, 2);
        CHECK_STATUS(rmf_cone_spline_approximate_dual(2, planes, 3, knots, 6, &box, 1e-4, 0, 1000, &spline, &err),
                     RMF_OK, "");
        CHECK(err <= 1e-4, "dual form within the tolerance");
        rmf_cone_spline_free(spline);
        CHECK_STATUS(rmf_cone_spline_approximate_dual(2, NULL, 3, knots, 6, &box, 1e-4, 0, 1000, &untouched, NULL),
                     RMF_ERROR_NULL_POINTER, "planes");
        CHECK_STATUS(rmf_cone_spline_approximate_dual(2, planes, 3, bad_knots, 6, &box, 1e-4, 0, 1000, &untouched, NULL),
                     RMF_ERROR_INVALID_INPUT, "knots");
        CHECK_STATUS(rmf_cone_spline_approximate_dual(2, planes, 3, knots, 5, &box, 1e-4, 0, 1000, &untouched, NULL),
                     RMF_ERROR_INVALID_INPUT, "knot_count");
        box.min = vec3(10, 10, 10);
        box.max = vec3(11, 11, 11);
        CHECK_STATUS(rmf_cone_spline_approximate_dual(2, planes, 3, knots, 6, &box, 1e-4, 0, 1000, &untouched, NULL),
                     RMF_ERROR_NO_SOLUTION, "misses the region");
    }
    /* Osculating cone splines. */
    {
        const double good[8] = {0.2, 0.3429, 0.4857, 0.6286, 0.7714, 0.9143, 1.0571, 1.2};
        const double far[3] = {0.2, 0.7, 1.2}, unordered[3] = {0.2, 0.9, 0.8};
        CHECK_STATUS(rmf_cone_spline_osculating(NULL, cubic, NULL, 0.2, 1.2, 0.5, 1.0, good, 8, &spline), RMF_OK, "");
        CHECK_STATUS(rmf_cone_spline_piece_count(spline, &n), RMF_OK, "");
        CHECK(n >= 15, "osculating segments and filling cones");
        rmf_cone_spline_free(spline);
        /* Cones too far apart for a consistent filling cone: their intervals are halved. */
        CHECK_STATUS(rmf_cone_spline_osculating(NULL, cubic, NULL, 0.2, 1.2, 0.5, 1.0, far, 3, &spline), RMF_OK, "");
        CHECK_STATUS(rmf_cone_spline_piece_count(spline, &n), RMF_OK, "");
        CHECK(n > 5, "widely spaced cones are subdivided");
        rmf_cone_spline_free(spline);
        CHECK_STATUS(rmf_cone_spline_osculating(NULL, cubic, NULL, 0.2, 1.2, 0.5, 1.0, unordered, 3, &untouched),
                     RMF_ERROR_INVALID_INPUT, "increasing");
        CHECK_STATUS(rmf_cone_spline_osculating(NULL, cubic, NULL, 0.2, 1.2, 0.5, 1.0, NULL, 3, &untouched),
                     RMF_ERROR_NULL_POINTER, "parameters");
    }
    CHECK(untouched == sentinel_spline(), "failing calls write nothing");
}

/* The smallest relative clearance of the vertices of a tangent-surface fit of the twisted
 * cubic over v in [v_min, v_max], from the exported data only: the selected rulings
 * x(t) + v e(t) (RMF_CONE_FIT_ELEMENTS) and the pieces. A vertex lies on every ruling of
 * its piece; it is measured on each bounding ruling of its piece that is a selected
 * ruling of the surface (the junction rulings inside a cone pair are not), as the distance
 * s along e(t) beyond the band, max(v_min - s, s - v_max) / (v_max - v_min). `matched`
 * receives how many (vertex, ruling) pairs were measured. */
static double cubic_fit_clearance(const RmfConeSpline *spline, double v_min, double v_max, size_t *matched) {
    double params[256], worst = INFINITY;
    size_t n = 0, count = 0, i, k;
    *matched = 0;
    if (rmf_cone_spline_fit_parameters(spline, RMF_CONE_FIT_ELEMENTS, params, 256, &n) != RMF_OK ||
        rmf_cone_spline_piece_count(spline, &count) != RMF_OK)
        return nan("");
    for (i = 0; i < count; i++) {
        RmfConePiece piece;
        if (rmf_cone_spline_piece(spline, i, &piece) != RMF_OK) return nan("");
        if (!piece.has_vertex) continue;
        for (k = 0; k < n; k++) {
            const RmfVec3 points[2] = {piece.start_point, piece.end_point};
            const RmfVec3 rulings[2] = {piece.start_ruling, piece.end_ruling};
            RmfVec3 x, d, e;
            int end;
            cubic(params[k], NULL, &x, &d);
            e = ne_unit(d);
            for (end = 0; end < 2; end++) {
                double s;
                if (ne_norm(ne_cross(rulings[end], e)) > 1e-9 ||
                    ne_norm(ne_cross(ne_sub(points[end], x), e)) > 1e-9)
                    continue; /* not this selected ruling */
                s = ne_dot(ne_sub(piece.vertex, x), e);
                worst = fmin(worst, fmax(v_min - s, s - v_max) / (v_max - v_min));
                ++*matched;
            }
        }
    }
    return worst;
}

/* rmf_cone_spline_fit_clearance: positive for fits and equal to the clearance computed
 * above from the exported data (within 1e-9 relative: both measure the same vertices on
 * the same rulings; the library does so in coordinates scaled to the surface); kept by the
 * development; refused for splines that are not fits, with nothing written. */
static void test_fit_clearance(void) {
    RmfConeSpline *spline = NULL, *flat = NULL, *hermite = NULL;
    double clearance = -1, flat_clearance = -1, untouched = -7, mine;
    size_t matched = 0;
    RmfConeElement els[2];
    CHECK_STATUS(rmf_cone_spline_approximate(NULL, cubic, NULL, 0.2, 1.2, 0.5, 1.0, 1e-3,
                                             RMF_CONE_RULE_MIN_VERTEX_DISTANCE, 1000, &spline, NULL),
                 RMF_OK, "");
    CHECK_STATUS(rmf_cone_spline_fit_clearance(spline, &clearance), RMF_OK, "");
    mine = cubic_fit_clearance(spline, 0.5, 1.0, &matched);
    printf("twisted cubic, v in [0.5, 1], 1e-3: vertex clearance %.6e (library), %.6e (from the pieces, %zu "
           "vertex-ruling pairs), difference %.1e\n",
           clearance, mine, matched, fabs(clearance - mine));
    CHECK(clearance > 0 && isfinite(clearance), "the vertices keep out of the region");
    CHECK(matched >= 2, "vertices measured on the selected rulings");
    CHECK(fabs(clearance - mine) <= 1e-9 * fmax(1.0, fabs(mine)), "the clearance measured from the exported data");
    CHECK_STATUS(rmf_cone_spline_develop(spline, &flat), RMF_OK, "");
    CHECK_STATUS(rmf_cone_spline_fit_clearance(flat, &flat_clearance), RMF_OK, "");
    CHECK(flat_clearance == clearance, "the development keeps the fit's clearance");
    rmf_cone_spline_free(flat);

    /* The dual form (a cone, box region): positive too. */
    {
        const double planes[12] = {0, 1, 0, -0.5, 0, 1, 1, -0.5, 0, 0, 1, -0.5};
        const double knots[6] = {0, 0, 0, 1, 1, 1};
        RmfConeSpline *dual = NULL;
        RmfBox box;
        double dual_clearance = -1;
        box.min = vec3(-3, -3, 1);
        box.max = vec3(3, 3, 2);
        CHECK_STATUS(rmf_cone_spline_approximate_dual(2, planes, 3, knots, 6, &box, 1e-4, 0, 1000, &dual, NULL),
                     RMF_OK, "");
        CHECK_STATUS(rmf_cone_spline_fit_clearance(dual, &dual_clearance), RMF_OK, "");
        printf("dual cone in a box, 1e-4: vertex clearance %.6e\n", dual_clearance);
        CHECK(dual_clearance > 0, "the dual fit's vertices keep out of the box's rulings");
        rmf_cone_spline_free(dual);
    }

    /* Not a fit: Hermite cone pairs and osculating cone splines have no fitted region. */
    els[0] = cubic_element(0.4, 2.5);
    els[1] = cubic_element(0.6, 2.5);
    CHECK_STATUS(rmf_cone_spline_hermite(els, 2, RMF_CONE_RULE_MIN_VERTEX_DISTANCE, 0, NULL, &hermite), RMF_OK, "");
    CHECK_STATUS(rmf_cone_spline_fit_clearance(hermite, &untouched), RMF_ERROR_INVALID_INPUT,
                 "not made by an approximation");
    rmf_cone_spline_free(hermite);
    {
        const double ts[3] = {0.2, 0.7, 1.2};
        RmfConeSpline *osculating = NULL;
        CHECK_STATUS(rmf_cone_spline_osculating(NULL, cubic, NULL, 0.2, 1.2, 0.5, 1.0, ts, 3, &osculating), RMF_OK, "");
        CHECK_STATUS(rmf_cone_spline_fit_clearance(osculating, &untouched), RMF_ERROR_INVALID_INPUT,
                     "no region of interest");
        rmf_cone_spline_free(osculating);
    }
    CHECK_STATUS(rmf_cone_spline_fit_clearance(NULL, &untouched), RMF_ERROR_NULL_POINTER, "spline");
    CHECK_STATUS(rmf_cone_spline_fit_clearance(spline, NULL), RMF_ERROR_NULL_POINTER, "clearance");
    CHECK(untouched == -7, "failing calls write nothing");
    rmf_cone_spline_free(spline);
}

/* The entry points with an options struct or a curve handle (0.2) give the splines of the
 * deprecated long calls, with the same fit; NULL options and a wrong struct_size are refused
 * with a message naming the argument, and nothing is written. */
static void test_option_struct_entry_points(void) {
    RmfConeApproximationOptions options;
    RmfConeSpline *old_spline = NULL, *spline = NULL, *untouched = sentinel_spline();
    RmfCurve *curve = NULL;
    double old_err = -1, err = -1, untouched_err = -7, old_params[64], params[64];
    size_t old_n = 0, n = 0, k;

    CHECK_STATUS(rmf_cone_approximation_options_init(&options), RMF_OK, "");
    CHECK(options.struct_size == sizeof options && options.tolerance == 0 &&
              options.rule == RMF_CONE_RULE_MIN_VERTEX_DISTANCE && options.max_pieces == 10000,
          "the defaults: size set, tolerance to be set, the default rule, 10000 pieces");
    CHECK_STATUS(rmf_cone_approximation_options_init(NULL), RMF_ERROR_NULL_POINTER, "out");
    CHECK_STATUS(rmf_callback_curve_create(cubic, NULL, 0.2, 1.2, &curve), RMF_OK, "");

    options.tolerance = 1e-3;
    CHECK_STATUS(rmf_cone_spline_approximate(NULL, cubic, NULL, 0.2, 1.2, 0.5, 1.0, 1e-3,
                                             RMF_CONE_RULE_MIN_VERTEX_DISTANCE, 100000, &old_spline, &old_err),
                 RMF_OK, "");
    CHECK_STATUS(rmf_cone_spline_approximate_with_options(curve, 0.5, 1.0, &options, &spline, &err), RMF_OK, "");
    CHECK(err == old_err && err > 0 && err <= 1e-3, "the same fit as rmf_cone_spline_approximate");
    CHECK_STATUS(rmf_cone_spline_fit_parameters(old_spline, RMF_CONE_FIT_ELEMENTS, old_params, 64, &old_n), RMF_OK, "");
    CHECK_STATUS(rmf_cone_spline_fit_parameters(spline, RMF_CONE_FIT_ELEMENTS, params, 64, &n), RMF_OK, "");
    CHECK(n == old_n && n >= 3, "the same number of rulings");
    for (k = 0; k < n && k < old_n; k++) CHECK(params[k] == old_params[k], "the same rulings");
    rmf_cone_spline_free(spline);
    rmf_cone_spline_free(old_spline);

    /* Bad input: each refused with its status and the argument named; nothing written. */
    CHECK_STATUS(rmf_cone_spline_approximate_with_options(curve, 0.5, 1.0, NULL, &untouched, &untouched_err),
                 RMF_ERROR_NULL_POINTER, "options");
    CHECK_STATUS(rmf_cone_spline_approximate_with_options(NULL, 0.5, 1.0, &options, &untouched, &untouched_err),
                 RMF_ERROR_NULL_POINTER, "curve");
    CHECK_STATUS(rmf_cone_spline_approximate_with_options(curve, 0.5, 1.0, &options, NULL, &untouched_err),
                 RMF_ERROR_NULL_POINTER, "out");
    options.struct_size = sizeof options + 8;
    CHECK_STATUS(rmf_cone_spline_approximate_with_options(curve, 0.5, 1.0, &options, &untouched, &untouched_err),
                 RMF_ERROR_INVALID_INPUT, "options->struct_size");
    options.struct_size = sizeof(size_t);
    CHECK_STATUS(rmf_cone_spline_approximate_with_options(curve, 0.5, 1.0, &options, &untouched, &untouched_err),
                 RMF_ERROR_INVALID_INPUT, "options->struct_size");
    options.struct_size = sizeof options;
    options.tolerance = 0;
    CHECK_STATUS(rmf_cone_spline_approximate_with_options(curve, 0.5, 1.0, &options, &untouched, &untouched_err),
                 RMF_ERROR_INVALID_INPUT, "options: tolerance");
    options.tolerance = 1e-3;
    options.rule = RMF_CONE_RULE_GIVEN;
    CHECK_STATUS(rmf_cone_spline_approximate_with_options(curve, 0.5, 1.0, &options, &untouched, &untouched_err),
                 RMF_ERROR_INVALID_INPUT, "options: rule");
    options.rule = 99;
    CHECK_STATUS(rmf_cone_spline_approximate_with_options(curve, 0.5, 1.0, &options, &untouched, &untouched_err),
                 RMF_ERROR_INVALID_INPUT, "options: rule");
    options.rule = RMF_CONE_RULE_MIN_VERTEX_DISTANCE;
    options.max_pieces = 1;
    CHECK_STATUS(rmf_cone_spline_approximate_with_options(curve, 0.5, 1.0, &options, &untouched, &untouched_err),
                 RMF_ERROR_INVALID_INPUT, "options: max_pieces");
    options.max_pieces = 6;
    options.tolerance = 1e-9;
    CHECK_STATUS(rmf_cone_spline_approximate_with_options(curve, 0.5, 1.0, &options, &untouched, &untouched_err),
                 RMF_ERROR_NOT_CONVERGED, "max_pieces = 6");
    options.max_pieces = 100000;
    options.tolerance = 1e-3;
    CHECK_STATUS(rmf_cone_spline_approximate_with_options(curve, -0.5, 1.0, &options, &untouched, &untouched_err),
                 RMF_ERROR_INVALID_INPUT, "contains 0");
    CHECK(untouched == sentinel_spline() && untouched_err == -7, "failing calls write nothing");

    /* The dual form with options: the spline of rmf_cone_spline_approximate_dual. */
    {
        const double planes[12] = {0, 1, 0, -0.5, 0, 1, 1, -0.5, 0, 0, 1, -0.5};
        const double knots[6] = {0, 0, 0, 1, 1, 1};
        RmfBox box;
        box.min = vec3(-3, -3, 1);
        box.max = vec3(3, 3, 2);
        options.tolerance = 1e-4;
        CHECK_STATUS(rmf_cone_spline_approximate_dual(2, planes, 3, knots, 6, &box, 1e-4, 0, 100000, &old_spline,
                                                      &old_err),
                     RMF_OK, "");
        CHECK_STATUS(rmf_cone_spline_approximate_dual_with_options(2, planes, 3, knots, 6, &box, &options, &spline,
                                                                   &err),
                     RMF_OK, "");
        CHECK(err == old_err && err <= 1e-4, "the same dual fit");
        CHECK_STATUS(rmf_cone_spline_piece_count(old_spline, &old_n), RMF_OK, "");
        CHECK_STATUS(rmf_cone_spline_piece_count(spline, &n), RMF_OK, "");
        CHECK(n == old_n, "the same pieces");
        rmf_cone_spline_free(spline);
        rmf_cone_spline_free(old_spline);
        CHECK_STATUS(rmf_cone_spline_approximate_dual_with_options(2, planes, 3, knots, 6, &box, NULL, &untouched,
                                                                   &untouched_err),
                     RMF_ERROR_NULL_POINTER, "options");
        options.struct_size = 0;
        CHECK_STATUS(rmf_cone_spline_approximate_dual_with_options(2, planes, 3, knots, 6, &box, &options, &untouched,
                                                                   &untouched_err),
                     RMF_ERROR_INVALID_INPUT, "options->struct_size");
        options.struct_size = sizeof options;
        CHECK_STATUS(rmf_cone_spline_approximate_dual_with_options(2, NULL, 3, knots, 6, &box, &options, &untouched,
                                                                   &untouched_err),
                     RMF_ERROR_NULL_POINTER, "planes");
        CHECK_STATUS(rmf_cone_spline_approximate_dual_with_options(2, planes, 3, knots, 5, &box, &options, &untouched,
                                                                   &untouched_err),
                     RMF_ERROR_INVALID_INPUT, "knot_count");
    }

    /* Osculating cones of a curve handle: the spline of rmf_cone_spline_osculating. */
    {
        const double good[8] = {0.2, 0.3429, 0.4857, 0.6286, 0.7714, 0.9143, 1.0571, 1.2};
        const double outside[3] = {0.1, 0.7, 1.2};
        RmfConePiece a, b;
        CHECK_STATUS(rmf_cone_spline_osculating(NULL, cubic, NULL, 0.2, 1.2, 0.5, 1.0, good, 8, &old_spline), RMF_OK, "");
        CHECK_STATUS(rmf_cone_spline_osculating_curve(curve, 0.5, 1.0, good, 8, &spline), RMF_OK, "");
        CHECK_STATUS(rmf_cone_spline_piece_count(old_spline, &old_n), RMF_OK, "");
        CHECK_STATUS(rmf_cone_spline_piece_count(spline, &n), RMF_OK, "");
        CHECK(n == old_n && n >= 15, "the same osculating pieces");
        for (k = 0; k < n && k < old_n; k++) {
            CHECK_STATUS(rmf_cone_spline_piece(old_spline, k, &a), RMF_OK, "");
            CHECK_STATUS(rmf_cone_spline_piece(spline, k, &b), RMF_OK, "");
            CHECK(a.kind == b.kind && a.half_angle == b.half_angle && a.segment_angle == b.segment_angle,
                  "the same pieces");
        }
        rmf_cone_spline_free(spline);
        rmf_cone_spline_free(old_spline);
        CHECK_STATUS(rmf_cone_spline_osculating_curve(NULL, 0.5, 1.0, good, 8, &untouched), RMF_ERROR_NULL_POINTER,
                     "curve");
        CHECK_STATUS(rmf_cone_spline_osculating_curve(curve, 0.5, 1.0, NULL, 8, &untouched), RMF_ERROR_NULL_POINTER,
                     "parameters");
        CHECK_STATUS(rmf_cone_spline_osculating_curve(curve, 0.5, 1.0, outside, 3, &untouched),
                     RMF_ERROR_INVALID_INPUT, "parameters[0]");
    }
    CHECK(untouched == sentinel_spline() && untouched_err == -7, "failing calls write nothing");
    rmf_curve_free(curve);
}

/* Issue 13 item 6: helix-tangent-surface rulings 0.001 apart (radius 1, pitch 0.5,
   distance 1.5 from the curve) were NO_SOLUTION for most t, and rmf_cone_spline_hermite
   failed from scale 1e15. Every pair of 500 joins, at scales 1e-200, 1, 1e15 and 1e200, and
   the end ruling of the last piece is the last element's. */
static RmfConeElement helix_element(double t, double scale) {
    RmfVec3 e = ne_unit(vec3(-sin(t), cos(t), 0.5));
    RmfConeElement el;
    el.point = ne_scale(ne_add(vec3(cos(t), sin(t), 0.5 * t), ne_scale(e, 1.5)), scale);
    el.ruling = e;
    el.side = vec3(-cos(t), -sin(t), 0); /* the rulings move towards the principal normal */
    return el;
}

static void test_close_rulings(void) {
    static const double scales[4] = {1e-200, 1.0, 1e15, 1e200};
    int k, s, joined = 0, tried = 0;
    double worst = 0;
    for (s = 0; s < 4; s++)
        for (k = 0; k < 500; k++) {
            double t = 0.004 + 0.06 * k;
            RmfConeElement els[2];
            RmfConeSpline *spline = NULL;
            size_t n = 0;
            els[0] = helix_element(t, scales[s]);
            els[1] = helix_element(t + 0.001, scales[s]);
            tried++;
            if (rmf_cone_spline_hermite(els, 2, RMF_CONE_RULE_MIN_VERTEX_DISTANCE, 0, NULL, &spline) != RMF_OK) {
                if (joined + 1 == tried) fprintf(stderr, "t = %g, scale %g: %s\n", t, scales[s], rmf_last_error());
                continue;
            }
            joined++;
            if (rmf_cone_spline_piece_count(spline, &n) == RMF_OK && n > 0) {
                RmfConePiece last;
                if (rmf_cone_spline_piece(spline, n - 1, &last) == RMF_OK)
                    worst = fmax(worst, ne_dist(last.end_ruling, els[1].ruling));
            }
            rmf_cone_spline_free(spline);
        }
    printf("helix rulings 0.001 apart: %d of %d pairs join (scales 1e-200 ... 1e200), end rulings within %.1e\n",
           joined, tried, worst);
    CHECK(joined == tried, "every pair of close rulings joins at every scale");
    CHECK(worst <= 1e-10, "the last piece ends on the last element's ruling");
}

int main(void) {
    test_hermite_surface_and_pieces();
    test_hermite_bad_input();
    test_approximations();
    test_fit_clearance();
    test_option_struct_entry_points();
    test_close_rulings();
    return rmf_check_exit_code("abi_cone_spline");
}
