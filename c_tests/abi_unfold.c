/*
 * Unfolding a face handed in as another kernel would (rmf_brep_create: a rational B-spline
 * cylinder patch with a window, its edges as NURBS curves, loops of edge uses), checked
 * with the suite's own arithmetic: the flat area from the loops' lines and arcs by Green's
 * theorem against R·Δθ·h less the window's, every edge of a cylinder's parallel circles
 * and rulings a line, the DXF's entities, marks flat ↔ formed, distances along a parallel
 * circle kept. A hyperbolic paraboloid is reported not developable and refused. Bad input
 * names the argument and leaves the out-pointer untouched.
 *
 * A whole sheet body: an L bracket (a rectangle 1 × 4 swept along line, quarter turn of
 * radius 3, line), its B-rep read through the rmf_brep_* views and handed back in by
 * rmf_brep_create as another kernel would, unfolded at k = 0.5 and 0.3: the flat area
 * against the neutral length by the suite's Green's theorem, one bend, the thickness,
 * the DXF's BEND layer, marks.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "rmf_check.h"

#define R 2.0

static RmfVec3 on_cylinder(double theta, double z) { return vec3(R * cos(theta), R * sin(theta), z); }

/* A circular arc of the cylinder at height z from t0 to t1 (≤ π/2 per segment) as a
 * rational quadratic NURBS of `segments` segments: 2·segments + 1 poles. */
typedef struct {
    RmfVec3 poles[5];
    double weights[5];
    double knots[8];
    RmfNurbsCurve view;
} Arc;

static void make_arc(Arc *a, double t0, double t1, double z, int segments) {
    double step = (t1 - t0) / segments, w = cos(0.5 * step);
    for (int s = 0; s < segments; s++) {
        double a0 = t0 + s * step, mid = a0 + 0.5 * step;
        a->poles[2 * s] = on_cylinder(a0, z);
        a->weights[2 * s] = 1.0;
        a->poles[2 * s + 1] = vec3(R * cos(mid) / w, R * sin(mid) / w, z);
        a->weights[2 * s + 1] = w;
    }
    a->poles[2 * segments] = on_cylinder(t1, z);
    a->weights[2 * segments] = 1.0;
    int k = 0;
    for (int i = 0; i < 3; i++) a->knots[k++] = 0.0;
    for (int s = 1; s < segments; s++) {
        a->knots[k++] = s;
        a->knots[k++] = s;
    }
    for (int i = 0; i < 3; i++) a->knots[k++] = segments;
    RmfNurbsCurve v = {2, (size_t)(2 * segments + 1), a->poles, a->weights, (size_t)k, a->knots};
    a->view = v;
}

typedef struct {
    RmfVec3 poles[2];
    double knots[4];
    RmfNurbsCurve view;
} Line;

static void make_line(Line *l, RmfVec3 a, RmfVec3 b) {
    l->poles[0] = a;
    l->poles[1] = b;
    l->knots[0] = l->knots[1] = 0.0;
    l->knots[2] = l->knots[3] = 1.0;
    RmfNurbsCurve v = {1, 2, l->poles, NULL, 4, l->knots};
    l->view = v;
}

/* Everything a cylinder patch θ ∈ [0, 2], z ∈ [0, 3] with the window θ ∈ [0.5, 1.5],
 * z ∈ [1, 2] needs to be handed in. */
typedef struct {
    Arc bottom, top, low, high;
    Line rulings[4];
    RmfVec3 surface_poles[10];
    double surface_weights[10];
    double knots_u[4];
    RmfVec3 vertices[8];
    RmfBrepEdge edges[8];
    RmfBrepFace face;
    RmfBrepLoop loops[2];
    RmfBrepUse uses[8];
    RmfBrepInput input;
} Patch;

static RmfBrepUse use_of(size_t edge, uint32_t forward) {
    RmfBrepUse u;
    memset(&u, 0, sizeof u);
    u.edge = edge;
    u.forward = forward;
    u.pcurve_kind = RMF_PCURVE_NONE;
    return u;
}

static void make_patch(Patch *p) {
    memset(p, 0, sizeof *p);
    make_arc(&p->bottom, 0.0, 2.0, 0.0, 2);
    make_arc(&p->top, 0.0, 2.0, 3.0, 2);
    make_arc(&p->low, 0.5, 1.5, 1.0, 1);
    make_arc(&p->high, 0.5, 1.5, 2.0, 1);
    make_line(&p->rulings[0], on_cylinder(2.0, 0.0), on_cylinder(2.0, 3.0));
    make_line(&p->rulings[1], on_cylinder(0.0, 0.0), on_cylinder(0.0, 3.0));
    make_line(&p->rulings[2], on_cylinder(1.5, 1.0), on_cylinder(1.5, 2.0));
    make_line(&p->rulings[3], on_cylinder(0.5, 1.0), on_cylinder(0.5, 2.0));
    for (int j = 0; j < 5; j++) {
        p->surface_poles[j] = p->bottom.poles[j];
        p->surface_poles[5 + j] = p->top.poles[j];
        p->surface_weights[j] = p->surface_weights[5 + j] = p->bottom.weights[j];
    }
    p->knots_u[0] = p->knots_u[1] = 0.0;
    p->knots_u[2] = p->knots_u[3] = 1.0;
    const RmfNurbsCurve *curves[8] = {&p->bottom.view,      &p->rulings[0].view, &p->top.view,
                                      &p->rulings[1].view,  &p->low.view,        &p->rulings[2].view,
                                      &p->high.view,        &p->rulings[3].view};
    for (size_t e = 0; e < 8; e++) {
        const RmfNurbsCurve *c = curves[e];
        p->vertices[e] = c->poles[0];
        p->edges[e].start = e;
        p->edges[e].end = e;
        p->edges[e].degenerate = 0;
        p->edges[e].curve = *c;
    }
    p->face.kind = RMF_BREP_SURFACE_NURBS;
    RmfNurbsSurface s = {1, 2, 2, 5, p->surface_poles, p->surface_weights, 4, p->knots_u,
                         p->bottom.view.knot_count, p->bottom.knots};
    p->face.nurbs = s;
    p->face.same_sense = 1;
    p->face.loop_count = 2;
    p->loops[0].outer = 1;
    p->loops[0].use_count = 4;
    p->loops[1].outer = 0;
    p->loops[1].use_count = 4;
    /* Outer: bottom, ruling at 2 up, top back, ruling at 0 down; the window the other way. */
    p->uses[0] = use_of(0, 1);
    p->uses[1] = use_of(1, 1);
    p->uses[2] = use_of(2, 0);
    p->uses[3] = use_of(3, 0);
    p->uses[4] = use_of(7, 1);
    p->uses[5] = use_of(6, 1);
    p->uses[6] = use_of(5, 0);
    p->uses[7] = use_of(4, 0);
    RmfBrepInput in = {8, p->vertices, 8, p->edges, 1, &p->face, p->loops, p->uses, 0};
    p->input = in;
}

/* Twice the signed area of a loop of lines and arcs (chords plus circular segments). */
static double loop_area(const RmfFlatEdge *e, size_t n) {
    double a = 0.0;
    for (size_t k = 0; k < n; k++) {
        a += e[k].from.x * e[k].to.y - e[k].to.x * e[k].from.y;
        if (e[k].kind == RMF_FLAT_EDGE_ARC) a += e[k].radius * e[k].radius * (e[k].sweep - sin(e[k].sweep));
    }
    return 0.5 * a;
}

static void check_cylinder_patch(void) {
    Patch p;
    make_patch(&p);
    RmfBrep *brep = NULL;
    CHECK_STATUS(rmf_brep_create(&p.input, &brep), RMF_OK, "");
    if (!brep) return;
    RmfDevelopability report;
    report.struct_size = sizeof report;
    CHECK_STATUS(rmf_face_developability(brep, 0, &report), RMF_OK, "");
    CHECK(report.kind == RMF_SURFACE_CIRCULAR_CYLINDER, "a rational B-spline cylinder is a circular cylinder");
    CHECK(report.curvature < 1e-9 && report.stretch == 0.0, "a cylinder is developable");

    RmfUnfoldOptions options;
    rmf_unfold_options_init(&options);
    RmfUnfoldedFace *face = NULL;
    CHECK_STATUS(rmf_unfold_face(brep, 0, &options, &face), RMF_OK, "");
    if (!face) {
        rmf_brep_free(brep);
        return;
    }
    size_t loops = 0;
    CHECK_STATUS(rmf_unfolded_face_loop_count(face, &loops), RMF_OK, "");
    CHECK(loops == 2, "the outline and the window");
    double area = 0.0, own = 0.0;
    for (size_t l = 0; l < loops && l < 2; l++) {
        size_t n = 0;
        CHECK_STATUS(rmf_unfolded_face_loop(face, l, NULL, 0, &n), RMF_OK, "");
        RmfFlatEdge edges[64];
        CHECK(n == 4, "four edges per loop");
        if (n > 64) continue;
        CHECK_STATUS(rmf_unfolded_face_loop(face, l, edges, 64, &n), RMF_OK, "");
        for (size_t k = 0; k < n; k++) {
            CHECK(edges[k].kind == RMF_FLAT_EDGE_LINE, "parallel circles and rulings develop into lines");
            const RmfFlatEdge *next = &edges[(k + 1) % n];
            CHECK(fabs(edges[k].to.x - next->from.x) + fabs(edges[k].to.y - next->from.y) < 1e-12,
                  "each edge starts where the one before ends");
        }
        double a = loop_area(edges, n);
        CHECK(l == 0 ? a > 0.0 : a < 0.0, "outline counter-clockwise, window clockwise");
        own += a;
    }
    CHECK_STATUS(rmf_unfolded_face_area(face, &area), RMF_OK, "");
    const double exact = R * 2.0 * 3.0 - R * 1.0 * 1.0;
    printf("unfold: cylinder patch with a window: area %.15g (own sum %.15g, exact %.15g)\n", area, own, exact);
    CHECK(fabs(own - exact) <= 1e-12 * exact, "the suite's area is R·Δθ·h less the window's");
    CHECK(fabs(area - own) <= 1e-12 * exact, "the library's area is the suite's");

    size_t bends = 99;
    CHECK_STATUS(rmf_unfolded_face_bend_lines(face, NULL, 0, &bends), RMF_OK, "");
    CHECK(bends == 0, "a cylinder face is one bend: no bend lines inside it");

    size_t length = 0;
    CHECK_STATUS(rmf_unfolded_face_dxf(face, NULL, 0, &length), RMF_OK, "");
    char *dxf = malloc(length + 1);
    if (dxf) {
        CHECK_STATUS(rmf_unfolded_face_dxf(face, dxf, length + 1, &length), RMF_OK, "");
        int lines = 0;
        for (const char *s = dxf; (s = strstr(s, "\nLINE\n")) != NULL; s++) lines++;
        CHECK(lines == 8 && strstr(dxf, "\nARC\n") == NULL, "eight LINE entities, no ARC");
        CHECK(strstr(dxf, "CUT") != NULL && strlen(dxf) == length, "layer CUT, the length given");
        free(dxf);
    }

    /* Marks: two points on the parallel circle z = 0.5 are R·Δθ apart when flat. */
    RmfVec3 marks[3] = {on_cylinder(0.2, 0.5), on_cylinder(1.7, 0.5), on_cylinder(1.0, 2.6)};
    RmfVec2 flat[3];
    RmfVec3 back[3];
    CHECK_STATUS(rmf_unfolded_face_to_flat(face, marks, 3, flat), RMF_OK, "");
    CHECK_STATUS(rmf_unfolded_face_to_formed(face, flat, 3, back), RMF_OK, "");
    double worst = 0.0;
    for (int i = 0; i < 3; i++)
        worst = fmax(worst, fabs(back[i].x - marks[i].x) + fabs(back[i].y - marks[i].y) + fabs(back[i].z - marks[i].z));
    double apart = hypot(flat[1].x - flat[0].x, flat[1].y - flat[0].y);
    printf("unfold: marks formed → flat → formed %.1e; along the circle %.15g (R·Δθ = %.15g)\n", worst,
           apart, R * 1.5);
    CHECK(worst <= 1e-13, "marks come back");
    CHECK(fabs(apart - R * 1.5) <= 1e-13, "lengths along a parallel circle are kept");

    RmfUnfoldedFace *untouched = (RmfUnfoldedFace *)&p;
    CHECK_STATUS(rmf_unfold_face(brep, 1, &options, &untouched), RMF_ERROR_INVALID_INPUT, "face = 1");
    CHECK(untouched == (RmfUnfoldedFace *)&p, "a failing call writes no out-pointer");
    size_t count = 0;
    CHECK_STATUS(rmf_unfolded_face_loop(face, 2, NULL, 0, &count), RMF_ERROR_INVALID_INPUT, "index = 2");
    marks[0].x = nan_value();
    CHECK_STATUS(rmf_unfolded_face_to_flat(face, marks, 1, flat), RMF_ERROR_INVALID_INPUT, "points[0]");
    options.tolerance = -1.0;
    CHECK_STATUS(rmf_unfold_face(brep, 0, &options, &untouched), RMF_ERROR_INVALID_INPUT, "tolerance");
    CHECK_STATUS(rmf_unfold_face(NULL, 0, NULL, &untouched), RMF_ERROR_NULL_POINTER, "brep");
    CHECK_STATUS(rmf_unfold_face(brep, 0, NULL, NULL), RMF_ERROR_NULL_POINTER, "out");
    rmf_unfolded_face_free(face);
    rmf_brep_free(brep);
}

static void check_bad_breps(void) {
    Patch p;
    RmfBrep *untouched = (RmfBrep *)&p;
    CHECK_STATUS(rmf_brep_create(NULL, &untouched), RMF_ERROR_NULL_POINTER, "input");
    make_patch(&p);
    p.uses[3].edge = 8;
    CHECK_STATUS(rmf_brep_create(&p.input, &untouched), RMF_ERROR_INVALID_INPUT, "uses[3].edge = 8");
    make_patch(&p);
    p.edges[1].curve.knot_count = 3;
    CHECK_STATUS(rmf_brep_create(&p.input, &untouched), RMF_ERROR_INVALID_INPUT, "edges[1].curve");
    make_patch(&p);
    p.face.kind = 9;
    CHECK_STATUS(rmf_brep_create(&p.input, &untouched), RMF_ERROR_INVALID_INPUT, "faces[0].kind = 9");
    make_patch(&p);
    p.edges[0].curve.poles = NULL;
    CHECK_STATUS(rmf_brep_create(&p.input, &untouched), RMF_ERROR_NULL_POINTER, "edges[0].curve.poles");
    make_patch(&p);
    p.vertices[2].y = inf_value();
    CHECK_STATUS(rmf_brep_create(&p.input, &untouched), RMF_ERROR_INVALID_INPUT, "vertices[2]");
    CHECK(untouched == (RmfBrep *)&p, "a failing call writes no out-pointer");

    /* An open loop: the window's last use dropped. */
    make_patch(&p);
    p.loops[1].use_count = 3;
    RmfBrep *brep = NULL;
    CHECK_STATUS(rmf_brep_create(&p.input, &brep), RMF_OK, "");
    RmfUnfoldedFace *face = NULL;
    CHECK_STATUS(rmf_unfold_face(brep, 0, NULL, &face), RMF_ERROR_INVALID_INPUT, "loop 1 is not closed");
    CHECK(face == NULL, "nothing written");
    rmf_brep_free(brep);
}

/* The hyperbolic paraboloid z = 0.4·x·y over the unit square: ruled, not developable. */
static void check_not_developable(void) {
    RmfVec3 poles[4] = {vec3(0, 0, 0), vec3(0, 1, 0), vec3(1, 0, 0), vec3(1, 1, 0.4)};
    double knots[4] = {0, 0, 1, 1};
    RmfVec3 corners[4] = {poles[0], poles[2], poles[3], poles[1]};
    RmfVec3 line_poles[4][2];
    RmfBrepEdge edges[4];
    RmfBrepUse uses[4];
    for (int k = 0; k < 4; k++) {
        line_poles[k][0] = corners[k];
        line_poles[k][1] = corners[(k + 1) % 4];
        RmfNurbsCurve c = {1, 2, line_poles[k], NULL, 4, knots};
        edges[k].start = (size_t)k;
        edges[k].end = (size_t)((k + 1) % 4);
        edges[k].degenerate = 0;
        edges[k].curve = c;
        uses[k] = use_of((size_t)k, 1);
    }
    RmfBrepFace face;
    memset(&face, 0, sizeof face);
    face.kind = RMF_BREP_SURFACE_NURBS;
    RmfNurbsSurface s = {1, 1, 2, 2, poles, NULL, 4, knots, 4, knots};
    face.nurbs = s;
    face.same_sense = 1;
    face.loop_count = 1;
    RmfBrepLoop loop = {1, 4};
    RmfBrepInput in = {4, corners, 4, edges, 1, &face, &loop, uses, 0};
    RmfBrep *brep = NULL;
    CHECK_STATUS(rmf_brep_create(&in, &brep), RMF_OK, "");
    if (!brep) return;
    RmfDevelopability report;
    report.struct_size = sizeof report;
    CHECK_STATUS(rmf_face_developability(brep, 0, &report), RMF_OK, "");
    printf("unfold: hyperbolic paraboloid: |K|·size² %.3g, stretch %.3g\n", report.curvature, report.stretch);
    CHECK(report.kind == RMF_SURFACE_NOT_DEVELOPABLE, "a hyperbolic paraboloid is not developable");
    CHECK(report.stretch > 1e-3 && report.stretch < 0.1, "it must stretch by some tenths of a percent");
    RmfUnfoldedFace *out = NULL;
    CHECK_STATUS(rmf_unfold_face(brep, 0, NULL, &out), RMF_ERROR_INVALID_INPUT, "not developable");
    CHECK(out == NULL, "nothing written");
    report.struct_size = 3;
    CHECK_STATUS(rmf_face_developability(brep, 0, &report), RMF_ERROR_INVALID_INPUT, "struct_size");
    rmf_brep_free(brep);
}

/* The library's B-rep of `shape`, read through its views and handed back in. */
typedef struct {
    RmfVec3 *vertices;
    RmfBrepEdge *edges;
    RmfBrepFace *faces;
    RmfBrepLoop *loops;
    RmfBrepUse *uses;
    RmfBrep *brep;
} Copied;

static RmfBrep *copied_brep(const RmfBrep *from, Copied *c) {
    RmfBrepCounts n;
    memset(c, 0, sizeof *c);
    if (rmf_brep_counts(from, &n) != RMF_OK) return NULL;
    size_t loops = 0, uses = 0;
    c->vertices = malloc(n.vertex_count * sizeof *c->vertices);
    c->edges = malloc(n.edge_count * sizeof *c->edges);
    c->faces = malloc(n.face_count * sizeof *c->faces);
    for (size_t i = 0; i < n.vertex_count; i++) rmf_brep_vertex(from, i, &c->vertices[i]);
    for (size_t i = 0; i < n.edge_count; i++) rmf_brep_edge(from, i, &c->edges[i]);
    for (size_t f = 0; f < n.face_count; f++) {
        rmf_brep_face(from, f, &c->faces[f]);
        loops += c->faces[f].loop_count;
    }
    c->loops = malloc(loops * sizeof *c->loops);
    size_t l = 0;
    for (size_t f = 0; f < n.face_count; f++)
        for (size_t k = 0; k < c->faces[f].loop_count; k++, l++) {
            rmf_brep_loop(from, f, k, &c->loops[l]);
            uses += c->loops[l].use_count;
        }
    c->uses = malloc(uses * sizeof *c->uses);
    size_t u = 0;
    l = 0;
    for (size_t f = 0; f < n.face_count; f++)
        for (size_t k = 0; k < c->faces[f].loop_count; k++, l++)
            for (size_t j = 0; j < c->loops[l].use_count; j++, u++) rmf_brep_use(from, f, k, j, &c->uses[u]);
    RmfBrepInput in = {n.vertex_count, c->vertices, n.edge_count, c->edges, n.face_count, c->faces,
                       c->loops, c->uses, n.solid};
    CHECK_STATUS(rmf_brep_create(&in, &c->brep), RMF_OK, "");
    return c->brep;
}

static void free_copied(Copied *c) {
    rmf_brep_free(c->brep);
    free(c->vertices);
    free(c->edges);
    free(c->faces);
    free(c->loops);
    free(c->uses);
}

static void check_l_bracket(void) {
    const double s = sqrt(0.5), t = 1.0, w = 4.0;
    RmfEdge wire[3] = {{RMF_EDGE_LINE, {vec3(0, 0, 0), vec3(10, 0, 0), vec3(0, 0, 0)}, NULL},
                       {RMF_EDGE_ARC, {vec3(10, 0, 0), vec3(10 + 3 * s, 3 - 3 * s, 0), vec3(13, 3, 0)}, NULL},
                       {RMF_EDGE_LINE, {vec3(13, 3, 0), vec3(13, 13, 0), vec3(0, 0, 0)}, NULL}};
    RmfVec3 corners[4] = {vec3(-0.5 * t, 0, 0), vec3(0.5 * t, 0, 0), vec3(0.5 * t, w, 0), vec3(-0.5 * t, w, 0)};
    RmfCurve *profile = NULL;
    CHECK_STATUS(rmf_curve_polygon(corners, 4, &profile), RMF_OK, "");
    RmfWireSweepOptions options;
    rmf_wire_sweep_options_init(&options);
    options.initial_normal = vec3(0, 1, 0);
    RmfShape *shape = NULL;
    CHECK_STATUS(rmf_wire_sweep(wire, 3, profile, NULL, 0, &options, &shape), RMF_OK, "");
    RmfBrep *made = NULL;
    if (shape) CHECK_STATUS(rmf_shape_brep(shape, &made), RMF_OK, "");
    Copied copy;
    RmfBrep *brep = made ? copied_brep(made, &copy) : NULL;
    for (int pass = 0; brep && pass < 2; pass++) {
        double k = pass == 0 ? 0.5 : 0.3;
        RmfUnfoldBodyOptions o;
        rmf_unfold_body_options_init(&o);
        o.tolerance = 1e-6;
        o.k_factor = k;
        RmfUnfoldedBody *body = NULL;
        CHECK_STATUS(rmf_unfold_body(brep, &o, &body), RMF_OK, "");
        if (!body) continue;
        double thickness = 0.0, area = 0.0;
        CHECK_STATUS(rmf_unfolded_body_thickness(body, &thickness), RMF_OK, "");
        CHECK(fabs(thickness - t) <= 1e-12, "the thickness is measured");
        size_t n = 0;
        CHECK_STATUS(rmf_unfolded_body_loop(body, 0, NULL, 0, &n), RMF_OK, "");
        RmfFlatEdge *edges = malloc(n * sizeof *edges);
        if (edges) {
            CHECK_STATUS(rmf_unfolded_body_loop(body, 0, edges, n, &n), RMF_OK, "");
            area = loop_area(edges, n);
            free(edges);
        }
        double neutral = 20.0 + 2.0 * atan(1.0) * (3.0 - 0.5 * t + k * t);
        printf("unfold: L bracket handed in (k = %.1f): flat area %.15g by the suite (w × neutral length %.15g)\n",
               k, area, w * neutral);
        CHECK(fabs(area - w * neutral) <= 1e-9 * w * neutral, "the flat area is the neutral length times the width");
        RmfBend bends[4];
        size_t count = 0;
        CHECK_STATUS(rmf_unfolded_body_bends(body, bends, 4, &count), RMF_OK, "");
        CHECK(count == 1 && fabs(bends[0].radius - 2.5) <= 1e-12 && bends[0].k_factor == k, "one bend, inner radius 2.5");
        size_t length = 0;
        CHECK_STATUS(rmf_unfolded_body_dxf(body, NULL, 0, &length), RMF_OK, "");
        char *dxf = malloc(length + 1);
        if (dxf) {
            CHECK_STATUS(rmf_unfolded_body_dxf(body, dxf, length + 1, &length), RMF_OK, "");
            CHECK(strstr(dxf, "BEND_UP") != NULL || strstr(dxf, "BEND_DOWN") != NULL, "the bend line on its layer");
            free(dxf);
        }
        RmfVec2 q = {5.0, 1.0};
        RmfVec3 x;
        RmfVec2 back;
        CHECK_STATUS(rmf_unfolded_body_to_formed(body, &q, 1, &x), RMF_OK, "");
        CHECK_STATUS(rmf_unfolded_body_to_flat(body, &x, 1, &back), RMF_OK, "");
        CHECK(fabs(back.x - q.x) + fabs(back.y - q.y) <= 1e-12, "marks come back");
        rmf_unfolded_body_free(body);
    }
    RmfUnfoldedBody *untouched = (RmfUnfoldedBody *)&copy;
    RmfUnfoldBodyOptions bad;
    rmf_unfold_body_options_init(&bad);
    bad.k_factor = 1.5;
    if (brep) CHECK_STATUS(rmf_unfold_body(brep, &bad, &untouched), RMF_ERROR_INVALID_INPUT, "outside [0, 1]");
    bad.k_factor = 0.5;
    bad.k_table_count = 2;
    if (brep) CHECK_STATUS(rmf_unfold_body(brep, &bad, &untouched), RMF_ERROR_NULL_POINTER, "k_table");
    CHECK(untouched == (RmfUnfoldedBody *)&copy, "a failing call writes no out-pointer");
    if (brep) free_copied(&copy);
    rmf_brep_free(made);
    rmf_shape_free(shape);
    rmf_curve_free(profile);
}

int main(void) {
    check_cylinder_patch();
    check_l_bracket();
    check_bad_breps();
    check_not_developable();
    return rmf_check_exit_code("abi_unfold");
}
