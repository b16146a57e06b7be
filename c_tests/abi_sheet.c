/*
 * C99 tests of the sheet-metal ABI (issue 15): options, a square-to-round transition,
 * its report, layer surfaces and boundaries, flat pattern, marks both ways and file
 * exports, its designed surface's cone spline; NULL pointers, bad options (struct_size,
 * thickness, K-factor, reference, tolerance), bad curves (open, not planar, crossing), marks
 * outside the part; the deprecated calls of a part held by a cone spline; a part between the rails of a ruled developable and of a
 * tangent surface, checked with the suite's own evaluator (edges against the rails, flat
 * area against the formed neutral layer). Every failure returns its status with a message naming the
 * argument and leaves out-pointers untouched; the program runs under valgrind and ASan.
 */
/* These tests call the deprecated wrappers on purpose (they keep working): no warning. */
#define RMF_DEPRECATED(note)
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "nurbs_eval.h"
#include "rmf_check.h"

#define vec3(x, y, z) ((RmfVec3){(x), (y), (z)})

static RmfSheetPart *sentinel_part(void) { return (RmfSheetPart *)(uintptr_t)0x5e5e; }

/* A closed polygon of degree-1 segments through n corners (the first repeated). */
static RmfCurve *polygon(const RmfVec3 *corners, size_t n) {
    RmfVec3 poles[16];
    double knots[20];
    size_t i;
    RmfCurve *curve = NULL;
    for (i = 0; i < n; i++) poles[i] = corners[i];
    poles[n] = corners[0];
    knots[0] = 0;
    for (i = 0; i <= n; i++) knots[i + 1] = (double)i;
    knots[n + 2] = (double)n;
    CHECK_STATUS(rmf_nurbs_curve_create(1, poles, NULL, n + 1, knots, n + 3, &curve), RMF_OK, "");
    return curve;
}

/* The circle about (cx, cy, cz) in a horizontal plane, four rational quadratic quarters. */
static RmfCurve *circle(double cx, double cy, double cz, double r) {
    RmfCurve *curve = NULL;
    CHECK_STATUS(rmf_curve_circle(vec3(cx, cy, cz), vec3(1, 0, 0), vec3(0, 1, 0), r, &curve), RMF_OK, "");
    return curve;
}

static RmfCurve *square(double half, double z) {
    const RmfVec3 c[4] = {vec3(-half, -half, z), vec3(half, -half, z), vec3(half, half, z), vec3(-half, half, z)};
    return polygon(c, 4);
}

static void test_options(void) {
    RmfSheetOptions o;
    CHECK_STATUS(rmf_sheet_options_init(&o), RMF_OK, "");
    CHECK(o.struct_size == sizeof(RmfSheetOptions), "struct_size");
    CHECK(o.tolerance == 1e-4 && o.thickness == 1.0 && o.k_factor == 0.5, "defaults");
    CHECK(o.reference == RMF_SHEET_REFERENCE_INNER && o.flat_tolerance == 0 && o.max_pieces == 10000, "defaults");
    CHECK_STATUS(rmf_sheet_options_init(NULL), RMF_ERROR_NULL_POINTER, "options");
}

/* Every bad option is refused by name, and `out` stays as it was. */
static void test_bad_options(RmfCurve *bottom, RmfCurve *top) {
    RmfSheetOptions o;
    RmfSheetPart *out = sentinel_part();
    rmf_sheet_options_init(&o);
    o.struct_size = 3;
    CHECK_STATUS(rmf_sheet_part_transition(bottom, top, &o, &out), RMF_ERROR_INVALID_INPUT, "options->struct_size");
    rmf_sheet_options_init(&o);
    o.thickness = 0;
    CHECK_STATUS(rmf_sheet_part_transition(bottom, top, &o, &out), RMF_ERROR_INVALID_INPUT, "options->thickness");
    o.thickness = -2;
    CHECK_STATUS(rmf_sheet_part_transition(bottom, top, &o, &out), RMF_ERROR_INVALID_INPUT, "options->thickness");
    o.thickness = nan_value();
    CHECK_STATUS(rmf_sheet_part_transition(bottom, top, &o, &out), RMF_ERROR_INVALID_INPUT, "options->thickness");
    rmf_sheet_options_init(&o);
    o.k_factor = 1.5;
    CHECK_STATUS(rmf_sheet_part_transition(bottom, top, &o, &out), RMF_ERROR_INVALID_INPUT, "options->k_factor");
    o.k_factor = -0.01;
    CHECK_STATUS(rmf_sheet_part_transition(bottom, top, &o, &out), RMF_ERROR_INVALID_INPUT, "options->k_factor");
    rmf_sheet_options_init(&o);
    o.reference = 9;
    CHECK_STATUS(rmf_sheet_part_transition(bottom, top, &o, &out), RMF_ERROR_INVALID_INPUT, "options->reference");
    rmf_sheet_options_init(&o);
    o.tolerance = 0;
    CHECK_STATUS(rmf_sheet_part_transition(bottom, top, &o, &out), RMF_ERROR_INVALID_INPUT, "options->tolerance");
    rmf_sheet_options_init(&o);
    o.max_pieces = 1;
    CHECK_STATUS(rmf_sheet_part_transition(bottom, top, &o, &out), RMF_ERROR_INVALID_INPUT, "options->max_pieces");
    rmf_sheet_options_init(&o);
    o.flat_tolerance = -1;
    CHECK_STATUS(rmf_sheet_part_transition(bottom, top, &o, &out), RMF_ERROR_INVALID_INPUT, "options->flat_tolerance");
    /* The designed surface as the outer face: the inner face would pass the corner cones'
     * vertices, whose bend radius is 0. */
    rmf_sheet_options_init(&o);
    o.reference = RMF_SHEET_REFERENCE_OUTER;
    o.tolerance = 1e-2;
    CHECK_STATUS(rmf_sheet_part_transition(bottom, top, &o, &out), RMF_ERROR_INVALID_INPUT, "bend radius");
    CHECK(out == sentinel_part(), "out untouched on failure");
}

static void test_bad_curves(RmfCurve *bottom, RmfCurve *top) {
    RmfSheetOptions o;
    RmfSheetPart *out = sentinel_part();
    const RmfVec3 open_poles[3] = {vec3(0, 0, 0), vec3(1, 0, 0), vec3(1, 1, 0)};
    const double open_knots[5] = {0, 0, 1, 2, 2};
    const RmfVec3 skew[4] = {vec3(0, 0, 0), vec3(1, 0, 0), vec3(1, 1, 0.2), vec3(0, 1, 0)};
    const RmfVec3 dart[4] = {vec3(0, 0, 0), vec3(2, 1, 0), vec3(0, 0.5, 0), vec3(-2, 1, 0)};
    RmfCurve *open = NULL, *bent = polygon(skew, 4), *concave = polygon(dart, 4), *low = circle(0, 0, -1, 0.5);
    rmf_sheet_options_init(&o);
    o.tolerance = 1e-2;
    CHECK_STATUS(rmf_nurbs_curve_create(1, open_poles, NULL, 3, open_knots, 5, &open), RMF_OK, "");
    CHECK_STATUS(rmf_sheet_part_transition(open, top, &o, &out), RMF_ERROR_INVALID_INPUT, "bottom is not closed");
    CHECK_STATUS(rmf_sheet_part_transition(bottom, bent, &o, &out), RMF_ERROR_INVALID_INPUT, "top is not planar");
    CHECK_STATUS(rmf_sheet_part_transition(concave, top, &o, &out), RMF_ERROR_INVALID_INPUT, "bottom is not convex");
    /* Two curves in one plane: neither lies on one side of the other's plane. */
    CHECK_STATUS(rmf_sheet_part_transition(bottom, bottom, &o, &out), RMF_ERROR_INVALID_INPUT,
                 "of the plane of bottom");
    CHECK_STATUS(rmf_sheet_part_transition(NULL, top, &o, &out), RMF_ERROR_NULL_POINTER, "bottom");
    CHECK_STATUS(rmf_sheet_part_transition(bottom, NULL, &o, &out), RMF_ERROR_NULL_POINTER, "top");
    CHECK_STATUS(rmf_sheet_part_transition(bottom, top, &o, NULL), RMF_ERROR_NULL_POINTER, "out");
    CHECK(out == sentinel_part(), "out untouched on failure");
    /* Below the square is a transition too (the curves are ordered by the call, not by z). */
    CHECK_STATUS(rmf_sheet_part_transition(bottom, low, &o, &out), RMF_OK, "");
    if (out != sentinel_part()) rmf_sheet_part_free(out);
    rmf_curve_free(open);
    rmf_curve_free(bent);
    rmf_curve_free(concave);
    rmf_curve_free(low);
}

/* The deprecated calls of a part held by an RmfConeSpline (this file defines RMF_DEPRECATED
 * away to call them): the same part as rmf_sheet_part_*, byte for byte in its files, and a
 * cone spline that holds no part refused naming the argument. */
static void check_deprecated_part_calls(RmfCurve *bottom, RmfCurve *top, const RmfSheetOptions *o,
                                        const RmfSheetPart *part, const RmfConeElement *els) {
    RmfConeSpline *old = NULL, *not_part = NULL, *untouched = (RmfConeSpline *)(uintptr_t)0x5e5e;
    RmfSheetReport a, b;
    RmfSurface *surface = NULL;
    size_t na = 0, nb = 0, la = 0, lb = 0;
    char *ta, *tb;
    CHECK_STATUS(rmf_cone_spline_transition(bottom, top, o, &old), RMF_OK, "");
    if (!old) return;
    CHECK_STATUS(rmf_cone_spline_part_report(old, &a), RMF_OK, "");
    CHECK_STATUS(rmf_sheet_part_report(part, &b), RMF_OK, "");
    CHECK(a.pieces == b.pieces && a.deviation == b.deviation && a.neutral == b.neutral, "the same report");
    CHECK_STATUS(rmf_cone_spline_flat_pattern(old, NULL, 0, &na), RMF_OK, "");
    CHECK_STATUS(rmf_sheet_part_flat_pattern(part, NULL, 0, &nb), RMF_OK, "");
    CHECK(na == nb && na > 0, "the same flat pattern");
    CHECK_STATUS(rmf_cone_spline_part_export(old, RMF_SHEET_FORMAT_STEP_SOLID, NULL, 0, &la), RMF_OK, "");
    CHECK_STATUS(rmf_sheet_part_export(part, RMF_SHEET_FORMAT_STEP_SOLID, NULL, 0, &lb), RMF_OK, "");
    ta = (char *)malloc(la + 1);
    tb = (char *)malloc(lb + 1);
    CHECK_STATUS(rmf_cone_spline_part_export(old, RMF_SHEET_FORMAT_STEP_SOLID, ta, la + 1, &la), RMF_OK, "");
    CHECK_STATUS(rmf_sheet_part_export(part, RMF_SHEET_FORMAT_STEP_SOLID, tb, lb + 1, &lb), RMF_OK, "");
    CHECK(la == lb && memcmp(ta, tb, la) == 0, "the same STEP solid, byte for byte");
    free(ta);
    free(tb);
    CHECK_STATUS(rmf_cone_spline_hermite(els, 2, RMF_CONE_RULE_MIN_VERTEX_DISTANCE, 0, NULL, &not_part), RMF_OK, "");
    CHECK_STATUS(rmf_cone_spline_part_report(not_part, &a), RMF_ERROR_INVALID_INPUT, "not a sheet-metal part");
    CHECK_STATUS(rmf_cone_spline_part_surface(not_part, RMF_SHEET_LAYER_NEUTRAL, &surface), RMF_ERROR_INVALID_INPUT,
                 "part");
    CHECK(surface == NULL, "nothing written");
    CHECK_STATUS(rmf_cone_spline_transition(NULL, top, o, &untouched), RMF_ERROR_NULL_POINTER, "bottom");
    CHECK(untouched == (RmfConeSpline *)(uintptr_t)0x5e5e, "out untouched on failure");
    rmf_cone_spline_free(not_part);
    rmf_cone_spline_free(old);
}

static void test_part(RmfCurve *bottom, RmfCurve *top) {
    RmfSheetOptions o;
    RmfSheetReport r;
    RmfSheetPart *part = NULL;
    RmfConeSpline *spline = NULL;
    RmfSurface *surface = NULL;
    RmfCurve *edge = NULL;
    RmfNurbsSurface view;
    RmfNurbsCurve edge_view;
    RmfFlatEdge *edges;
    RmfVec2 flat[3], back[3], sentinel2 = {7, 7};
    RmfVec3 points[3], normals[3], sentinel3 = vec3(7, 7, 7);
    RmfConeElement els[2] = {{{0, 0, 0}, {0, 0, 1}, {1, 0, 0}}, {{1, 0, 0}, {0, 0, 1}, {1, 0.2, 0}}};
    size_t count = 0, n_edges = 0, length = 0, i, cut = 0;
    char *text;
    double worst = 0;
    rmf_sheet_options_init(&o);
    o.tolerance = 1e-2;
    o.thickness = 0.02;
    o.k_factor = 0.4;
    CHECK_STATUS(rmf_sheet_part_transition(bottom, top, &o, &part), RMF_OK, "");
    if (!part) return;
    CHECK_STATUS(rmf_sheet_part_report(part, &r), RMF_OK, "");
    CHECK(r.closed == 1 && r.pieces > 8, "a closed transition of several pieces");
    CHECK(r.edge_distance[0] <= 1e-2 && r.edge_distance[1] <= 1e-2 && r.deviation <= 1e-2, "within the tolerance");
    CHECK(fabs(r.neutral - 0.4 * 0.02) < 1e-15 && fabs(r.outer - 0.02) < 1e-15 && r.inner == 0, "layers");
    CHECK(r.bend_radius == 0, "corner cones have their vertex on the bottom edge");
    CHECK_STATUS(rmf_sheet_part_cone_spline(part, &spline), RMF_OK, "");
    CHECK_STATUS(rmf_cone_spline_piece_count(spline, &count), RMF_OK, "");
    CHECK(count == r.pieces, "the part's designed surface is a cone spline of its pieces");
    /* The neutral layer as one NURBS; its first row lies at k·t from the square's plane on
     * the flat triangles. */
    CHECK_STATUS(rmf_sheet_part_surface(part, RMF_SHEET_LAYER_NEUTRAL, &surface), RMF_OK, "");
    if (surface) {
        CHECK_STATUS(rmf_surface_nurbs(surface, &view), RMF_OK, "");
        CHECK(view.degree_u == 1 && view.pole_count_u == 2, "degree 1 along the rulings");
        rmf_surface_free(surface);
    }
    CHECK_STATUS(rmf_sheet_part_boundary(part, RMF_SHEET_LAYER_REFERENCE, RMF_SHEET_SIDE_SECOND, &edge), RMF_OK, "");
    if (edge) {
        CHECK_STATUS(rmf_curve_nurbs(edge, &edge_view), RMF_OK, "");
        for (i = 0; i <= 200; i++) {
            RmfVec3 d[3];
            const double t = edge_view.knots[edge_view.knot_count - 1] * (double)i / 200.0;
            ne_curve_derivatives(&edge_view, t, d);
            /* The top circle: centre (0.1, 0, 1), radius 0.3, plane z = 1. */
            worst = fmax(worst, fabs(hypot(d[0].x - 0.1, d[0].y) - 0.3) + fabs(d[0].z - 1));
        }
        CHECK(worst <= 1e-2, "the top edge within the tolerance of the circle (own evaluator)");
        rmf_curve_free(edge);
    }
    /* Flat pattern: size query, too small a buffer, the edges. */
    CHECK_STATUS(rmf_sheet_part_flat_pattern(part, NULL, 0, &n_edges), RMF_OK, "");
    CHECK(n_edges > 8, "edges counted");
    edges = (RmfFlatEdge *)calloc(n_edges, sizeof(RmfFlatEdge));
    count = 0;
    CHECK_STATUS(rmf_sheet_part_flat_pattern(part, edges, 2, &count), RMF_ERROR_BUFFER_TOO_SMALL, "need");
    CHECK(count == n_edges, "the needed count is written");
    CHECK_STATUS(rmf_sheet_part_flat_pattern(part, edges, n_edges, &count), RMF_OK, "");
    for (i = 0; i < n_edges; i++) cut += edges[i].layer == RMF_FLAT_CUT;
    for (i = 0; i < cut; i++) {
        const RmfFlatEdge *a = &edges[i], *b = &edges[(i + 1) % cut];
        CHECK(a->to.x == b->from.x && a->to.y == b->from.y, "the outline is closed");
    }
    /* Marks: three points inside the pattern (on the first bend line), there and back. */
    for (i = 0; i < n_edges; i++)
        if (edges[i].layer == RMF_FLAT_BEND) break;
    if (i < n_edges) {
        size_t k;
        for (k = 0; k < 3; k++) {
            const double s = 0.25 * (double)(k + 1);
            flat[k].x = edges[i].from.x + s * (edges[i].to.x - edges[i].from.x);
            flat[k].y = edges[i].from.y + s * (edges[i].to.y - edges[i].from.y);
        }
        CHECK_STATUS(rmf_sheet_part_flat_to_surface(part, flat, 3, RMF_SHEET_LAYER_NEUTRAL, points, normals), RMF_OK, "");
        CHECK_STATUS(rmf_sheet_part_surface_to_flat(part, points, 3, RMF_SHEET_LAYER_NEUTRAL, 1e-12, back), RMF_OK, "");
        for (k = 0; k < 3; k++) {
            CHECK(hypot(back[k].x - flat[k].x, back[k].y - flat[k].y) < 1e-13, "marks round trip");
            CHECK(fabs(ne_norm(normals[k]) - 1) < 1e-14, "unit normals");
        }
        CHECK_STATUS(rmf_sheet_part_flat_to_surface(part, flat, 3, RMF_SHEET_LAYER_OUTER, points, NULL), RMF_OK, "");
        flat[2].x = 1e3;
        points[0] = sentinel3;
        CHECK_STATUS(rmf_sheet_part_flat_to_surface(part, flat, 3, RMF_SHEET_LAYER_NEUTRAL, points, NULL),
                     RMF_ERROR_INVALID_INPUT, "flat[2]");
        CHECK(points[0].x == 7, "nothing written on failure");
        CHECK_STATUS(rmf_sheet_part_flat_to_surface(part, flat, 3, 17, points, NULL), RMF_ERROR_INVALID_INPUT, "layer");
        CHECK_STATUS(rmf_sheet_part_flat_to_surface(part, flat, 1, RMF_SHEET_LAYER_OUTER, points, NULL), RMF_OK, "");
        points[1] = vec3(5, 5, 5);
        back[0] = sentinel2;
        CHECK_STATUS(rmf_sheet_part_surface_to_flat(part, points, 2, RMF_SHEET_LAYER_OUTER, 1e-6, back),
                     RMF_ERROR_INVALID_INPUT, "points[1]");
        CHECK(back[0].x == 7, "nothing written on failure");
        CHECK_STATUS(rmf_sheet_part_surface_to_flat(part, points, 2, RMF_SHEET_LAYER_OUTER, -1, back),
                     RMF_ERROR_INVALID_INPUT, "max_distance");
        CHECK_STATUS(rmf_sheet_part_flat_to_surface(part, NULL, 3, RMF_SHEET_LAYER_NEUTRAL, points, NULL),
                     RMF_ERROR_NULL_POINTER, "flat");
        CHECK_STATUS(rmf_sheet_part_surface_to_flat(part, points, 3, RMF_SHEET_LAYER_NEUTRAL, 1, NULL),
                     RMF_ERROR_NULL_POINTER, "flat");
    }
    free(edges);
    /* Exports: size query, too small, the text with its NUL. */
    CHECK_STATUS(rmf_sheet_part_export(part, RMF_SHEET_FORMAT_DXF, NULL, 0, &length), RMF_OK, "");
    text = (char *)malloc(length + 1);
    CHECK_STATUS(rmf_sheet_part_export(part, RMF_SHEET_FORMAT_DXF, text, length, &length),
                 RMF_ERROR_BUFFER_TOO_SMALL, "NUL");
    CHECK_STATUS(rmf_sheet_part_export(part, RMF_SHEET_FORMAT_DXF, text, length + 1, &length), RMF_OK, "");
    CHECK(text[length] == '\0' && strstr(text, "ARC") && strstr(text, "BEND") && !strstr(text, "POLYLINE"), "DXF");
    free(text);
    CHECK_STATUS(rmf_sheet_part_export(part, RMF_SHEET_FORMAT_STEP_SOLID, NULL, 0, &length), RMF_OK, "");
    text = (char *)malloc(length + 1);
    CHECK_STATUS(rmf_sheet_part_export(part, RMF_SHEET_FORMAT_STEP_SOLID, text, length + 1, &length), RMF_OK, "");
    CHECK(strstr(text, "MANIFOLD_SOLID_BREP") && strstr(text, "CLOSED_SHELL"), "a STEP solid");
    {
        /* The same solid in OpenCascade's B-rep text: one face record per STEP face, the
           solid the root. */
        size_t step_faces = 0, occ_faces = 0, occ_length = 0;
        char *occ;
        for (const char *at = text; (at = strstr(at, "ADVANCED_FACE(")) != NULL; ++at) ++step_faces;
        CHECK_STATUS(rmf_sheet_part_export(part, RMF_SHEET_FORMAT_OCC_BREP, NULL, 0, &occ_length), RMF_OK, "");
        occ = (char *)malloc(occ_length + 1);
        CHECK_STATUS(rmf_sheet_part_export(part, RMF_SHEET_FORMAT_OCC_BREP, occ, occ_length, &occ_length),
                     RMF_ERROR_BUFFER_TOO_SMALL, "NUL");
        CHECK_STATUS(rmf_sheet_part_export(part, RMF_SHEET_FORMAT_OCC_BREP, occ, occ_length + 1, &occ_length),
                     RMF_OK, "");
        for (const char *at = occ; (at = strstr(at, "\nFa\n")) != NULL; ++at) ++occ_faces;
        CHECK(strncmp(occ, "\nCASCADE Topology V1, (c) Matra-Datavision\n", 43) == 0 && occ_faces == step_faces &&
                  step_faces > 8 && strstr(occ, "\nSo\n") && strcmp(occ + occ_length - 6, "\n+1 0\n") == 0,
              "the OpenCascade B-rep text of the STEP solid");
        free(occ);
    }
    free(text);
    CHECK_STATUS(rmf_sheet_part_export(part, 99, NULL, 0, &length), RMF_ERROR_INVALID_INPUT, "format");
    CHECK_STATUS(rmf_sheet_part_export(part, RMF_SHEET_FORMAT_SVG, NULL, 0, NULL), RMF_ERROR_NULL_POINTER, "length");
    CHECK_STATUS(rmf_sheet_part_export(part, RMF_SHEET_FORMAT_SVG, NULL, 5, &length), RMF_ERROR_NULL_POINTER, "buffer");
    CHECK_STATUS(rmf_sheet_part_report(NULL, &r), RMF_ERROR_NULL_POINTER, "part");
    CHECK_STATUS(rmf_sheet_part_cone_spline(part, NULL), RMF_ERROR_NULL_POINTER, "out");
    CHECK_STATUS(rmf_sheet_part_report(part, NULL), RMF_ERROR_NULL_POINTER, "report");
    CHECK_STATUS(rmf_sheet_part_boundary(part, RMF_SHEET_LAYER_INNER, 4, &edge), RMF_ERROR_INVALID_INPUT, "side");
    check_deprecated_part_calls(bottom, top, &o, part, els);
    rmf_sheet_part_free(part);
    /* The cone spline outlives the part it came from. */
    CHECK_STATUS(rmf_cone_spline_piece_count(spline, &count), RMF_OK, "");
    CHECK(count == r.pieces, "the cone spline stays valid after rmf_sheet_part_free");
    rmf_cone_spline_free(spline);
}

/* The rail x(t) + s x'(t) of the twisted cubic x = (t, t², t³). */
static RmfVec3 rail(double s, double t) { return vec3(t + s, t * t + 2 * s * t, t * t * t + 3 * s * t * t); }

/* Distance from p to the rail s over t ∈ [0.2, 1.2]: a dense scan, then golden sections. */
static double rail_distance(double s, RmfVec3 p) {
    const int n = 4000;
    const double g = 0.5 * (sqrt(5.0) - 1.0);
    double best = 0.2, d = INFINITY, lo, hi;
    int i, k;
    for (i = 0; i <= n; i++) {
        const double t = 0.2 + (double)i / n, e = ne_dist(rail(s, t), p);
        if (e < d) d = e, best = t;
    }
    lo = fmax(0.2, best - 1.0 / n);
    hi = fmin(1.2, best + 1.0 / n);
    for (k = 0; k < 100; k++) {
        const double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
        if (ne_dist(rail(s, a), p) < ne_dist(rail(s, b), p))
            hi = b;
        else
            lo = a;
    }
    return fmin(d, ne_dist(rail(s, 0.5 * (lo + hi)), p));
}

/* The Bézier poles of the cubic rail s on [a, b] by blossoming: x's blossom plus s times
 * that of x′ (degree 2, written as a cubic). */
static RmfVec3 rail_pole(double s, double a, double b, int i) {
    double u[3];
    int k;
    double m, sym2, prod;
    for (k = 0; k < 3; k++) u[k] = k < i ? b : a;
    m = (u[0] + u[1] + u[2]) / 3;
    sym2 = (u[0] * u[1] + u[0] * u[2] + u[1] * u[2]) / 3;
    prod = u[0] * u[1] * u[2];
    return vec3(m + s, sym2 + 2 * s * m, prod + 3 * s * sym2);
}

/* Area of a NURBS surface by 8 × 8 Gauss–Legendre points per knot span (own evaluator). */
static double nurbs_area(const RmfNurbsSurface *view) {
    static const double x[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
                                0.1834346424956498,  0.5255324099163290,  0.7966664774136267,  0.9602898564975363};
    static const double w[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
                                0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
    double area = 0;
    size_t a, b;
    int i, j;
    for (a = 0; a + 1 < view->knot_count_u; a++) {
        const double u0 = view->knots_u[a], u1 = view->knots_u[a + 1];
        if (u1 <= u0) continue;
        for (b = 0; b + 1 < view->knot_count_v; b++) {
            const double v0 = view->knots_v[b], v1 = view->knots_v[b + 1];
            if (v1 <= v0) continue;
            for (i = 0; i < 8; i++)
                for (j = 0; j < 8; j++) {
                    RmfVec3 d[3][3], n;
                    ne_surface_derivatives(view, u0 + 0.5 * (u1 - u0) * (x[i] + 1), v0 + 0.5 * (v1 - v0) * (x[j] + 1), d);
                    n = vec3(d[1][0].y * d[0][1].z - d[1][0].z * d[0][1].y, d[1][0].z * d[0][1].x - d[1][0].x * d[0][1].z,
                             d[1][0].x * d[0][1].y - d[1][0].y * d[0][1].x);
                    area += 0.25 * (u1 - u0) * (v1 - v0) * w[i] * w[j] * ne_norm(n);
                }
        }
    }
    return area;
}

/* Signed area enclosed by the cutting outline: chords, plus the circular segments of arcs. */
static double outline_area(const RmfFlatEdge *edges, size_t n) {
    double twice = 0;
    size_t i;
    for (i = 0; i < n; i++) {
        if (edges[i].layer != RMF_FLAT_CUT) continue;
        twice += edges[i].from.x * edges[i].to.y - edges[i].from.y * edges[i].to.x;
        if (edges[i].kind == RMF_FLAT_EDGE_ARC)
            twice += edges[i].radius * edges[i].radius * (edges[i].sweep - sin(edges[i].sweep));
    }
    return 0.5 * twice;
}

/* The part between the rails x + x′/2 and x + x′ of the twisted cubic's tangent surface
 * (a degree (1, 3) NURBS): its edges against the rails and its flat pattern's area
 * against the formed neutral layer's, both with the suite's own evaluator; the tangent
 * surface form; bad inputs. */
static void test_rails(void) {
    RmfVec3 poles[8];
    static const double knots_u[4] = {0, 0, 1, 1}, knots_v[8] = {0.2, 0.2, 0.2, 0.2, 1.2, 1.2, 1.2, 1.2};
    static const RmfVec3 saddle_poles[4] = {{-1, -1, 1}, {-1, 1, -1}, {1, -1, -1}, {1, 1, 1}};
    static const double unit[4] = {0, 0, 1, 1};
    RmfSurface *surface = NULL, *saddle = NULL, *neutral = NULL;
    RmfSheetPart *part = NULL, *untouched = sentinel_part();
    RmfSheetOptions o;
    RmfSheetReport r;
    RmfNurbsSurface view;
    RmfFlatEdge *edges = NULL;
    RmfCurve *curve = NULL;
    size_t n_edges = 0, count = 0;
    int i, side;
    for (i = 0; i < 4; i++) {
        poles[i] = rail_pole(0.5, 0.2, 1.2, i);
        poles[4 + i] = rail_pole(1.0, 0.2, 1.2, i);
    }
    CHECK_STATUS(rmf_nurbs_surface_create(1, 3, poles, NULL, 2, 4, knots_u, 4, knots_v, 8, &surface), RMF_OK, "");
    rmf_sheet_options_init(&o);
    o.tolerance = 1e-4;
    o.thickness = 0.02;
    o.flat_tolerance = 1e-9;
    CHECK_STATUS(rmf_sheet_part_between_rails(surface, &o, &part), RMF_OK, "");
    if (part) {
        double worst[2] = {0, 0}, flat, formed = 0;
        CHECK_STATUS(rmf_sheet_part_report(part, &r), RMF_OK, "");
        CHECK(r.closed == 0 && r.pieces >= 2, "an open part of several pieces");
        CHECK(r.deviation <= 1e-4 && r.edge_distance[0] <= 1e-4 && r.edge_distance[1] <= 1e-4, "within the tolerance");
        for (side = 0; side < 2; side++) {
            RmfCurve *edge = NULL;
            RmfNurbsCurve ev;
            CHECK_STATUS(rmf_sheet_part_boundary(part, RMF_SHEET_LAYER_REFERENCE, (uint32_t)side, &edge), RMF_OK, "");
            if (!edge) continue;
            CHECK_STATUS(rmf_curve_nurbs(edge, &ev), RMF_OK, "");
            for (i = 0; i <= 400; i++) {
                RmfVec3 d[3];
                const double t0 = ev.knots[0], t1 = ev.knots[ev.knot_count - 1];
                ne_curve_derivatives(&ev, t0 + (t1 - t0) * i / 400.0, d);
                worst[side] = fmax(worst[side], rail_distance(side ? 1.0 : 0.5, d[0]));
            }
            rmf_curve_free(edge);
        }
        printf("  ruled part between rails: %zu pieces, edges %.3e / %.3e from the rails (own evaluator)\n", r.pieces,
               worst[0], worst[1]);
        CHECK(worst[0] <= 1e-4 && worst[1] <= 1e-4, "the edges lie within the tolerance of the rails");
        CHECK(worst[0] > 1e-9 || worst[1] > 1e-9, "the measurement sees the fit (not trivially zero)");
        CHECK_STATUS(rmf_sheet_part_flat_pattern(part, NULL, 0, &n_edges), RMF_OK, "");
        edges = (RmfFlatEdge *)calloc(n_edges, sizeof(RmfFlatEdge));
        CHECK_STATUS(rmf_sheet_part_flat_pattern(part, edges, n_edges, &count), RMF_OK, "");
        flat = outline_area(edges, count);
        CHECK_STATUS(rmf_sheet_part_surface(part, RMF_SHEET_LAYER_NEUTRAL, &neutral), RMF_OK, "");
        if (neutral) {
            CHECK_STATUS(rmf_surface_nurbs(neutral, &view), RMF_OK, "");
            formed = nurbs_area(&view);
            rmf_surface_free(neutral);
        }
        printf("  flat area %.12f vs formed neutral %.12f (relative %.1e)\n", flat, formed, fabs(flat - formed) / formed);
        CHECK(flat > 0 && fabs(flat - formed) <= 1e-9 * formed, "flat area = formed neutral area to 1e-9");
        free(edges);
        rmf_sheet_part_free(part);
    }
    /* The tangent surface form: the twisted cubic itself, rails at 0.3 and 0.9. */
    {
        RmfVec3 cp[4];
        static const double knots[8] = {0.2, 0.2, 0.2, 0.2, 1.2, 1.2, 1.2, 1.2};
        for (i = 0; i < 4; i++) cp[i] = rail_pole(0.0, 0.2, 1.2, i);
        CHECK_STATUS(rmf_nurbs_curve_create(3, cp, NULL, 4, knots, 8, &curve), RMF_OK, "");
        part = NULL;
        CHECK_STATUS(rmf_sheet_part_tangent(curve, 0.3, 0.9, &o, &part), RMF_OK, "");
        if (part) {
            CHECK_STATUS(rmf_sheet_part_report(part, &r), RMF_OK, "");
            CHECK(r.edge_distance[0] <= 1e-4 && r.edge_distance[1] <= 1e-4, "tangent part within the tolerance");
            rmf_sheet_part_free(part);
        }
        CHECK_STATUS(rmf_sheet_part_tangent(curve, -0.3, 0.9, &o, &untouched), RMF_ERROR_INVALID_INPUT, "contains 0");
        CHECK_STATUS(rmf_sheet_part_tangent(curve, 0.9, 0.3, &o, &untouched), RMF_ERROR_INVALID_INPUT, "v_min");
        CHECK_STATUS(rmf_sheet_part_tangent(curve, NAN, 0.3, &o, &untouched), RMF_ERROR_INVALID_INPUT, "v_min");
        CHECK_STATUS(rmf_sheet_part_tangent(NULL, 0.3, 0.9, &o, &untouched), RMF_ERROR_NULL_POINTER, "curve");
        CHECK_STATUS(rmf_sheet_part_tangent(curve, 0.3, 0.9, &o, NULL), RMF_ERROR_NULL_POINTER, "out");
        rmf_curve_free(curve);
    }
    /* Bad inputs: not developable, NULL, bad options; nothing written. */
    CHECK_STATUS(rmf_nurbs_surface_create(1, 1, saddle_poles, NULL, 2, 2, unit, 4, unit, 4, &saddle), RMF_OK, "");
    CHECK_STATUS(rmf_sheet_part_between_rails(saddle, &o, &untouched), RMF_ERROR_INVALID_INPUT, "not developable");
    CHECK_STATUS(rmf_sheet_part_between_rails(NULL, &o, &untouched), RMF_ERROR_NULL_POINTER, "surface");
    CHECK_STATUS(rmf_sheet_part_between_rails(surface, &o, NULL), RMF_ERROR_NULL_POINTER, "out");
    o.k_factor = -0.1;
    CHECK_STATUS(rmf_sheet_part_between_rails(surface, &o, &untouched), RMF_ERROR_INVALID_INPUT, "options->k_factor");
    CHECK(untouched == sentinel_part(), "failing calls write nothing");
    rmf_surface_free(saddle);
    rmf_surface_free(surface);
}

int main(void) {
    RmfCurve *bottom = square(0.5, 0), *top = circle(0.1, 0, 1, 0.3);
    test_options();
    if (bottom && top) {
        test_bad_options(bottom, top);
        test_bad_curves(bottom, top);
        test_part(bottom, top);
    }
    test_rails();
    rmf_curve_free(bottom);
    rmf_curve_free(top);
    return rmf_check_exit_code("abi_sheet");
}
