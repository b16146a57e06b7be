/*
 * C99 tests of the sheet-metal ABI (issue 15): options, a square-to-round transition,
 * its report, layer surfaces and boundaries, flat pattern, marks both ways and file
 * exports; NULL pointers, bad options (struct_size, thickness, K-factor, reference,
 * tolerance), bad curves (open, not planar, crossing), marks outside the part and
 * handles that are not parts. Every failure returns its status with a message naming the
 * argument and leaves out-pointers untouched; the program runs under valgrind and ASan.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "nurbs_eval.h"
#include "rmf_check.h"

#define vec3(x, y, z) ((RmfVec3){(x), (y), (z)})

static RmfConeSpline *sentinel_part(void) { return (RmfConeSpline *)(uintptr_t)0x5e5e; }

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
    static const double xs[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, ys[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
    static const double knots[12] = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
    RmfVec3 poles[9];
    double weights[9];
    RmfCurve *curve = NULL;
    int i;
    for (i = 0; i < 9; i++) {
        poles[i] = vec3(cx + r * xs[i], cy + r * ys[i], cz);
        weights[i] = i % 2 ? sqrt(0.5) : 1.0;
    }
    CHECK_STATUS(rmf_nurbs_curve_create(2, poles, weights, 9, knots, 12, &curve), RMF_OK, "");
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
    CHECK(o.reference == RMF_SHEET_REFERENCE_INNER && o.flat_tolerance == 0 && o.max_pieces == 100000, "defaults");
    CHECK_STATUS(rmf_sheet_options_init(NULL), RMF_ERROR_NULL_POINTER, "options");
}

/* Every bad option is refused by name, and `out` stays as it was. */
static void test_bad_options(RmfCurve *bottom, RmfCurve *top) {
    RmfSheetOptions o;
    RmfConeSpline *out = sentinel_part();
    rmf_sheet_options_init(&o);
    o.struct_size = 3;
    CHECK_STATUS(rmf_cone_spline_transition(bottom, top, &o, &out), RMF_ERROR_INVALID_INPUT, "options->struct_size");
    rmf_sheet_options_init(&o);
    o.thickness = 0;
    CHECK_STATUS(rmf_cone_spline_transition(bottom, top, &o, &out), RMF_ERROR_INVALID_INPUT, "options->thickness");
    o.thickness = -2;
    CHECK_STATUS(rmf_cone_spline_transition(bottom, top, &o, &out), RMF_ERROR_INVALID_INPUT, "options->thickness");
    o.thickness = nan_value();
    CHECK_STATUS(rmf_cone_spline_transition(bottom, top, &o, &out), RMF_ERROR_INVALID_INPUT, "options->thickness");
    rmf_sheet_options_init(&o);
    o.k_factor = 1.5;
    CHECK_STATUS(rmf_cone_spline_transition(bottom, top, &o, &out), RMF_ERROR_INVALID_INPUT, "options->k_factor");
    o.k_factor = -0.01;
    CHECK_STATUS(rmf_cone_spline_transition(bottom, top, &o, &out), RMF_ERROR_INVALID_INPUT, "options->k_factor");
    rmf_sheet_options_init(&o);
    o.reference = 9;
    CHECK_STATUS(rmf_cone_spline_transition(bottom, top, &o, &out), RMF_ERROR_INVALID_INPUT, "options->reference");
    rmf_sheet_options_init(&o);
    o.tolerance = 0;
    CHECK_STATUS(rmf_cone_spline_transition(bottom, top, &o, &out), RMF_ERROR_INVALID_INPUT, "options->tolerance");
    rmf_sheet_options_init(&o);
    o.max_pieces = 1;
    CHECK_STATUS(rmf_cone_spline_transition(bottom, top, &o, &out), RMF_ERROR_INVALID_INPUT, "options->max_pieces");
    rmf_sheet_options_init(&o);
    o.flat_tolerance = -1;
    CHECK_STATUS(rmf_cone_spline_transition(bottom, top, &o, &out), RMF_ERROR_INVALID_INPUT, "options->flat_tolerance");
    /* The designed surface as the outer face: the inner face would pass the corner cones'
     * vertices, whose bend radius is 0. */
    rmf_sheet_options_init(&o);
    o.reference = RMF_SHEET_REFERENCE_OUTER;
    o.tolerance = 1e-2;
    CHECK_STATUS(rmf_cone_spline_transition(bottom, top, &o, &out), RMF_ERROR_INVALID_INPUT, "bend radius");
    CHECK(out == sentinel_part(), "out untouched on failure");
}

static void test_bad_curves(RmfCurve *bottom, RmfCurve *top) {
    RmfSheetOptions o;
    RmfConeSpline *out = sentinel_part();
    const RmfVec3 open_poles[3] = {vec3(0, 0, 0), vec3(1, 0, 0), vec3(1, 1, 0)};
    const double open_knots[5] = {0, 0, 1, 2, 2};
    const RmfVec3 skew[4] = {vec3(0, 0, 0), vec3(1, 0, 0), vec3(1, 1, 0.2), vec3(0, 1, 0)};
    const RmfVec3 dart[4] = {vec3(0, 0, 0), vec3(2, 1, 0), vec3(0, 0.5, 0), vec3(-2, 1, 0)};
    RmfCurve *open = NULL, *bent = polygon(skew, 4), *concave = polygon(dart, 4), *low = circle(0, 0, -1, 0.5);
    rmf_sheet_options_init(&o);
    o.tolerance = 1e-2;
    CHECK_STATUS(rmf_nurbs_curve_create(1, open_poles, NULL, 3, open_knots, 5, &open), RMF_OK, "");
    CHECK_STATUS(rmf_cone_spline_transition(open, top, &o, &out), RMF_ERROR_INVALID_INPUT, "bottom is not closed");
    CHECK_STATUS(rmf_cone_spline_transition(bottom, bent, &o, &out), RMF_ERROR_INVALID_INPUT, "top is not planar");
    CHECK_STATUS(rmf_cone_spline_transition(concave, top, &o, &out), RMF_ERROR_INVALID_INPUT, "bottom is not convex");
    /* Two curves in one plane cross each other's planes. */
    CHECK_STATUS(rmf_cone_spline_transition(bottom, bottom, &o, &out), RMF_ERROR_INVALID_INPUT, "cross");
    CHECK_STATUS(rmf_cone_spline_transition(NULL, top, &o, &out), RMF_ERROR_NULL_POINTER, "bottom");
    CHECK_STATUS(rmf_cone_spline_transition(bottom, NULL, &o, &out), RMF_ERROR_NULL_POINTER, "top");
    CHECK_STATUS(rmf_cone_spline_transition(bottom, top, &o, NULL), RMF_ERROR_NULL_POINTER, "out");
    CHECK(out == sentinel_part(), "out untouched on failure");
    /* Below the square is a transition too (the curves are ordered by the call, not by z). */
    CHECK_STATUS(rmf_cone_spline_transition(bottom, low, &o, &out), RMF_OK, "");
    if (out != sentinel_part()) rmf_cone_spline_free(out);
    rmf_curve_free(open);
    rmf_curve_free(bent);
    rmf_curve_free(concave);
    rmf_curve_free(low);
}

static void test_part(RmfCurve *bottom, RmfCurve *top) {
    RmfSheetOptions o;
    RmfSheetReport r;
    RmfConeSpline *part = NULL, *not_part = NULL;
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
    CHECK_STATUS(rmf_cone_spline_transition(bottom, top, &o, &part), RMF_OK, "");
    if (!part) return;
    CHECK_STATUS(rmf_cone_spline_part_report(part, &r), RMF_OK, "");
    CHECK(r.closed == 1 && r.pieces > 8, "a closed transition of several pieces");
    CHECK(r.edge_distance[0] <= 1e-2 && r.edge_distance[1] <= 1e-2 && r.deviation <= 1e-2, "within the tolerance");
    CHECK(fabs(r.neutral - 0.4 * 0.02) < 1e-15 && fabs(r.outer - 0.02) < 1e-15 && r.inner == 0, "layers");
    CHECK(r.bend_radius == 0, "corner cones have their vertex on the bottom edge");
    CHECK_STATUS(rmf_cone_spline_piece_count(part, &count), RMF_OK, "");
    CHECK(count == r.pieces, "the part is a cone spline of its pieces");
    /* The neutral layer as one NURBS; its first row lies at k·t from the square's plane on
     * the flat triangles. */
    CHECK_STATUS(rmf_cone_spline_part_surface(part, RMF_SHEET_LAYER_NEUTRAL, &surface), RMF_OK, "");
    if (surface) {
        CHECK_STATUS(rmf_surface_nurbs(surface, &view), RMF_OK, "");
        CHECK(view.degree_u == 1 && view.pole_count_u == 2, "degree 1 along the rulings");
        rmf_surface_free(surface);
    }
    CHECK_STATUS(rmf_cone_spline_part_boundary(part, RMF_SHEET_LAYER_REFERENCE, RMF_SHEET_SIDE_SECOND, &edge), RMF_OK, "");
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
    CHECK_STATUS(rmf_cone_spline_flat_pattern(part, NULL, 0, &n_edges), RMF_OK, "");
    CHECK(n_edges > 8, "edges counted");
    edges = (RmfFlatEdge *)calloc(n_edges, sizeof(RmfFlatEdge));
    count = 0;
    CHECK_STATUS(rmf_cone_spline_flat_pattern(part, edges, 2, &count), RMF_ERROR_BUFFER_TOO_SMALL, "need");
    CHECK(count == n_edges, "the needed count is written");
    CHECK_STATUS(rmf_cone_spline_flat_pattern(part, edges, n_edges, &count), RMF_OK, "");
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
        CHECK_STATUS(rmf_cone_spline_flat_to_surface(part, flat, 3, RMF_SHEET_LAYER_NEUTRAL, points, normals), RMF_OK, "");
        CHECK_STATUS(rmf_cone_spline_surface_to_flat(part, points, 3, RMF_SHEET_LAYER_NEUTRAL, 1e-12, back), RMF_OK, "");
        for (k = 0; k < 3; k++) {
            CHECK(hypot(back[k].x - flat[k].x, back[k].y - flat[k].y) < 1e-13, "marks round trip");
            CHECK(fabs(ne_norm(normals[k]) - 1) < 1e-14, "unit normals");
        }
        CHECK_STATUS(rmf_cone_spline_flat_to_surface(part, flat, 3, RMF_SHEET_LAYER_OUTER, points, NULL), RMF_OK, "");
        flat[2].x = 1e3;
        points[0] = sentinel3;
        CHECK_STATUS(rmf_cone_spline_flat_to_surface(part, flat, 3, RMF_SHEET_LAYER_NEUTRAL, points, NULL),
                     RMF_ERROR_INVALID_INPUT, "flat[2]");
        CHECK(points[0].x == 7, "nothing written on failure");
        CHECK_STATUS(rmf_cone_spline_flat_to_surface(part, flat, 3, 17, points, NULL), RMF_ERROR_INVALID_INPUT, "layer");
        CHECK_STATUS(rmf_cone_spline_flat_to_surface(part, flat, 1, RMF_SHEET_LAYER_OUTER, points, NULL), RMF_OK, "");
        points[1] = vec3(5, 5, 5);
        back[0] = sentinel2;
        CHECK_STATUS(rmf_cone_spline_surface_to_flat(part, points, 2, RMF_SHEET_LAYER_OUTER, 1e-6, back),
                     RMF_ERROR_INVALID_INPUT, "points[1]");
        CHECK(back[0].x == 7, "nothing written on failure");
        CHECK_STATUS(rmf_cone_spline_surface_to_flat(part, points, 2, RMF_SHEET_LAYER_OUTER, -1, back),
                     RMF_ERROR_INVALID_INPUT, "max_distance");
        CHECK_STATUS(rmf_cone_spline_flat_to_surface(part, NULL, 3, RMF_SHEET_LAYER_NEUTRAL, points, NULL),
                     RMF_ERROR_NULL_POINTER, "flat");
        CHECK_STATUS(rmf_cone_spline_surface_to_flat(part, points, 3, RMF_SHEET_LAYER_NEUTRAL, 1, NULL),
                     RMF_ERROR_NULL_POINTER, "flat");
    }
    free(edges);
    /* Exports: size query, too small, the text with its NUL. */
    CHECK_STATUS(rmf_cone_spline_part_export(part, RMF_SHEET_FORMAT_DXF, NULL, 0, &length), RMF_OK, "");
    text = (char *)malloc(length + 1);
    CHECK_STATUS(rmf_cone_spline_part_export(part, RMF_SHEET_FORMAT_DXF, text, length, &length),
                 RMF_ERROR_BUFFER_TOO_SMALL, "NUL");
    CHECK_STATUS(rmf_cone_spline_part_export(part, RMF_SHEET_FORMAT_DXF, text, length + 1, &length), RMF_OK, "");
    CHECK(text[length] == '\0' && strstr(text, "ARC") && strstr(text, "BEND") && !strstr(text, "POLYLINE"), "DXF");
    free(text);
    CHECK_STATUS(rmf_cone_spline_part_export(part, RMF_SHEET_FORMAT_STEP_SOLID, NULL, 0, &length), RMF_OK, "");
    text = (char *)malloc(length + 1);
    CHECK_STATUS(rmf_cone_spline_part_export(part, RMF_SHEET_FORMAT_STEP_SOLID, text, length + 1, &length), RMF_OK, "");
    CHECK(strstr(text, "MANIFOLD_SOLID_BREP") && strstr(text, "CLOSED_SHELL"), "a STEP solid");
    free(text);
    CHECK_STATUS(rmf_cone_spline_part_export(part, 99, NULL, 0, &length), RMF_ERROR_INVALID_INPUT, "format");
    CHECK_STATUS(rmf_cone_spline_part_export(part, RMF_SHEET_FORMAT_SVG, NULL, 0, NULL), RMF_ERROR_NULL_POINTER, "length");
    CHECK_STATUS(rmf_cone_spline_part_export(part, RMF_SHEET_FORMAT_SVG, NULL, 5, &length), RMF_ERROR_NULL_POINTER, "buffer");
    /* A cone spline that is not a part. */
    CHECK_STATUS(rmf_cone_spline_hermite(els, 2, RMF_CONE_RULE_MIN_VERTEX_DISTANCE, 0, NULL, &not_part), RMF_OK, "");
    CHECK_STATUS(rmf_cone_spline_part_report(not_part, &r), RMF_ERROR_INVALID_INPUT, "not a sheet-metal part");
    CHECK_STATUS(rmf_cone_spline_part_surface(not_part, RMF_SHEET_LAYER_NEUTRAL, &surface), RMF_ERROR_INVALID_INPUT, "part");
    CHECK_STATUS(rmf_cone_spline_part_report(NULL, &r), RMF_ERROR_NULL_POINTER, "part");
    CHECK_STATUS(rmf_cone_spline_part_report(part, NULL), RMF_ERROR_NULL_POINTER, "report");
    CHECK_STATUS(rmf_cone_spline_part_boundary(part, RMF_SHEET_LAYER_INNER, 4, &edge), RMF_ERROR_INVALID_INPUT, "side");
    rmf_cone_spline_free(not_part);
    rmf_cone_spline_free(part);
}

int main(void) {
    RmfCurve *bottom = square(0.5, 0), *top = circle(0.1, 0, 1, 0.3);
    test_options();
    if (bottom && top) {
        test_bad_options(bottom, top);
        test_bad_curves(bottom, top);
        test_part(bottom, top);
    }
    rmf_curve_free(bottom);
    rmf_curve_free(top);
    return rmf_check_exit_code("abi_sheet");
}
