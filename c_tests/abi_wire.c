/*
 * C99 tests of the wire sweep ABI (rmf_wire_sweep, RmfShape): a pipe route of lines and an
 * arc, polylines with round and miter corners, a closed NURBS; every figure measured from
 * the exported NURBS views with the suite's own evaluator (nurbs_eval.c): distance of the
 * faces from the spine, orthogonality of the parameter lines, and the enclosed volume by
 * the divergence theorem (Gauss–Legendre on every knot span) against the closed forms.
 * Then the bad inputs of issue 18: each returns its status with a message naming the edge,
 * joint, loop or option, leaves the out-pointer untouched and writes no file. Runs under
 * valgrind and AddressSanitizer (no leaks).
 */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "nurbs_eval.h"
#include "rmf_check.h"

#define vec3(x, y, z) ((RmfVec3){(x), (y), (z)})

static const double PI = 3.14159265358979323846;

/* Gauss–Legendre nodes and weights on [0, 1] (Newton on the Legendre polynomial). */
#define GAUSS 16
static double gauss_x[GAUSS], gauss_w[GAUSS];
static void gauss_init(void) {
    for (int i = 0; i < GAUSS; ++i) {
        double x = cos(PI * (i + 0.75) / (GAUSS + 0.5)), dp = 1;
        for (int it = 0; it < 100; ++it) {
            double p0 = 1, p1 = x;
            for (int k = 2; k <= GAUSS; ++k) {
                double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            dp = GAUSS * (x * p1 - p0) / (x * x - 1);
            double dx = p1 / dp;
            x -= dx;
            if (fabs(dx) < 1e-16) break;
        }
        gauss_x[i] = 0.5 * (1 - x);
        gauss_w[i] = 1.0 / ((1 - x * x) * dp * dp) * 2 * 0.5;
    }
}

/* Distinct knots of a clamped knot vector. */
static size_t breaks_of(const double *knots, size_t count, double *out) {
    size_t n = 0;
    for (size_t k = 0; k < count; ++k)
        if (n == 0 || knots[k] != out[n - 1]) out[n++] = knots[k];
    return n;
}

/* ∫∫ S · (S_u × S_v) over a surface, Gauss on every knot span. */
static double flux(const RmfNurbsSurface *s) {
    double bu[512], bv[512], total = 0;
    size_t nu = breaks_of(s->knots_u, s->knot_count_u, bu), nv = breaks_of(s->knots_v, s->knot_count_v, bv);
    for (size_t a = 0; a + 1 < nu; ++a)
        for (size_t b = 0; b + 1 < nv; ++b)
            for (int i = 0; i < GAUSS; ++i)
                for (int j = 0; j < GAUSS; ++j) {
                    RmfVec3 d[3][3];
                    double u = bu[a] + (bu[a + 1] - bu[a]) * gauss_x[i], v = bv[b] + (bv[b + 1] - bv[b]) * gauss_x[j];
                    ne_surface_derivatives(s, u, v, d);
                    total += gauss_w[i] * gauss_w[j] * (bu[a + 1] - bu[a]) * (bv[b + 1] - bv[b]) *
                             ne_dot(d[0][0], ne_cross(d[1][0], d[0][1]));
                }
    return total;
}

/* ½ ∮ ((C − o) × C') · n over a closed curve: the area it bounds in the plane (o, n). */
static double loop_area(const RmfNurbsCurve *c, RmfVec3 o, RmfVec3 n) {
    double br[512], total = 0;
    size_t nb = breaks_of(c->knots, c->knot_count, br);
    for (size_t a = 0; a + 1 < nb; ++a)
        for (int i = 0; i < GAUSS; ++i) {
            RmfVec3 d[3];
            ne_curve_derivatives(c, br[a] + (br[a + 1] - br[a]) * gauss_x[i], d);
            total += 0.5 * gauss_w[i] * (br[a + 1] - br[a]) * ne_dot(ne_cross(ne_sub(d[0], o), d[1]), n);
        }
    return total;
}

/* The enclosed volume ⅓ ∮ x · n dA, with the suite's evaluator only. */
static double volume(const RmfShape *shape) {
    double total = 0;
    for (size_t f = 0; f < rmf_shape_face_count(shape); ++f) {
        RmfShapeFace face;
        CHECK_STATUS(rmf_shape_face(shape, f, &face), RMF_OK, "");
        if (face.kind == RMF_FACE_SWEPT) {
            RmfNurbsSurface view;
            CHECK_STATUS(rmf_surface_nurbs(face.surface, &view), RMF_OK, "");
            total += (face.reversed ? -1 : 1) * flux(&view);
        } else {
            double area = 0;
            for (size_t l = 0; l < face.loop_count; ++l) {
                const RmfCurve *c = NULL;
                RmfNurbsCurve view;
                CHECK_STATUS(rmf_shape_face_loop(shape, f, l, &c), RMF_OK, "");
                CHECK_STATUS(rmf_curve_nurbs(c, &view), RMF_OK, "");
                area += loop_area(&view, face.plane_origin, face.plane_normal);
            }
            total += ne_dot(face.plane_origin, face.plane_normal) * area;
        }
    }
    return total / 3;
}

static RmfCurve *nurbs(uint32_t degree, const RmfVec3 *poles, const double *weights, size_t n, const double *knots) {
    RmfCurve *c = NULL;
    CHECK_STATUS(rmf_nurbs_curve_create(degree, poles, weights, n, knots, n + degree + 1, &c), RMF_OK, "");
    return c;
}

/* The circle of radius r about the origin, four rational quarters. */
static RmfCurve *circle(double r) {
    RmfCurve *curve = NULL;
    CHECK_STATUS(rmf_curve_circle(vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0), r, &curve), RMF_OK, "");
    return curve;
}

/* The square of half side a, counter-clockwise. */
static RmfCurve *square(double a) {
    const RmfVec3 p[5] = {vec3(a, a, 0), vec3(-a, a, 0), vec3(-a, -a, 0), vec3(a, -a, 0), vec3(a, a, 0)};
    const double k[7] = {0, 0, 1, 2, 3, 4, 4};
    return nurbs(1, p, NULL, 5, k);
}

static RmfEdge line(RmfVec3 a, RmfVec3 b) {
    RmfEdge e = {RMF_EDGE_LINE, {a, b, vec3(0, 0, 0)}, NULL};
    return e;
}

static RmfEdge arc(RmfVec3 a, RmfVec3 m, RmfVec3 b) {
    RmfEdge e = {RMF_EDGE_ARC, {a, m, b}, NULL};
    return e;
}

/* Line (10) – quarter arc of radius 5 – line (10); its length 20 + 2.5π. */
static void pipe_route(RmfEdge e[3]) {
    const double s = 0.70710678118654752440;
    e[0] = line(vec3(0, 0, 0), vec3(10, 0, 0));
    e[1] = arc(vec3(10, 0, 0), vec3(10 + 5 * s, 5 - 5 * s, 0), vec3(15, 5, 0));
    e[2] = line(vec3(15, 5, 0), vec3(15, 15, 0));
}

/* Distance of a point from the pipe route's spine. */
static double from_spine(RmfVec3 p) {
    if (p.x <= 10) return hypot(p.y, p.z);
    if (p.y >= 5) return hypot(p.x - 15, p.z);
    return hypot(hypot(p.x - 10, p.y - 5) - 5, p.z);
}

static void test_options(void) {
    RmfWireSweepOptions o;
    CHECK_STATUS(rmf_wire_sweep_options_init(&o), RMF_OK, "");
    CHECK(o.struct_size == sizeof o && o.tolerance == 1e-4 && o.join_tolerance == 1e-7, "defaults");
    CHECK(o.corner == RMF_CORNER_ROUND && o.corner_radius == 0 && o.solid == 1 && o.closure_symmetry == 0,
          "round corners, default radius, solids");
    CHECK(o.frame == RMF_FRAME_RMF && o.frame_direction.x == 0 && o.frame_direction.y == 0 &&
              o.frame_direction.z == 0 && o.scale_start == 1 && o.scale_end == 1,
          "the RMF, no fixed direction, scale 1 at both ends");
    CHECK(RMF_FRAME_RMF == 0 && RMF_FRAME_FRENET == 1 && RMF_FRAME_FIXED == 2 && RMF_FRAME_GUIDE == 3,
          "frame codes fixed");
    CHECK(o.guide_edges == NULL && o.guide_edge_count == 0, "no guide");
    CHECK(o.method == RMF_SPINE_PH_RMF, "curve edges along the PH cubic spline's rational RMF by default");
    CHECK(o.scale_knots == NULL && o.scale_knot_count == 0, "no knots in the scale law by default");
    CHECK(RMF_SPINE_PH_RMF == 0 && RMF_SPINE_FRENET == 1 && RMF_SPINE_MOBIUS == 2 && RMF_SPINE_RRMF == 3,
          "method codes fixed");
    CHECK_STATUS(rmf_wire_sweep_options_init(NULL), RMF_ERROR_NULL_POINTER, "options");
}

/* rmf_shape_step gives the file's text (the product named after the file's stem), with a size
   query, and refuses a buffer without room for the NUL, writing only the length. */
static void check_step_text_is_the_file(const RmfShape *shape, const char *path) {
    char stem[512];
    const char *base = strrchr(path, '/') ? strrchr(path, '/') + 1 : path;
    snprintf(stem, sizeof stem, "%s", base);
    if (strrchr(stem, '.')) *strrchr(stem, '.') = 0;
    size_t length = 0, again = 0;
    CHECK_STATUS(rmf_shape_step(shape, stem, NULL, 0, &length), RMF_OK, "");
    char *text = malloc(length + 1), *file_text = malloc(length + 2);
    FILE *file = fopen(path, "rb");
    if (!text || !file_text || !file) {
        CHECK(0, "buffers and the file");
        free(text), free(file_text);
        if (file) fclose(file);
        return;
    }
    size_t read = fread(file_text, 1, length + 1, file);
    fclose(file);
    memset(text, 'x', length + 1);
    CHECK_STATUS(rmf_shape_step(shape, stem, text, length, &again), RMF_ERROR_BUFFER_TOO_SMALL, "need");
    CHECK(again == length && text[0] == 'x', "too small: the length, no text");
    CHECK_STATUS(rmf_shape_step(shape, stem, text, length + 1, &again), RMF_OK, "");
    CHECK(read == length && again == length && text[length] == 0 && memcmp(text, file_text, length) == 0,
          "the text is the file, byte for byte");
    CHECK_STATUS(rmf_shape_step(shape, NULL, text, 0, NULL), RMF_ERROR_NULL_POINTER, "length");
    CHECK_STATUS(rmf_shape_step(shape, NULL, NULL, 8, &again), RMF_ERROR_NULL_POINTER, "buffer");
    CHECK_STATUS(rmf_shape_step(NULL, NULL, NULL, 0, &again), RMF_ERROR_NULL_POINTER, "shape");
    CHECK_STATUS(rmf_shape_step(shape, "\xff", NULL, 0, &again), RMF_ERROR_INVALID_INPUT, "name is not UTF-8");
    free(text);
    free(file_text);
}

/* OpenCascade's B-rep text: size query, too small a buffer, the text itself (one "Fa"
   record per face of the shape's B-rep, the root last), NULLs. */
static void check_occ_brep_text(const RmfShape *shape) {
    size_t length = 0, again = 0;
    CHECK_STATUS(rmf_shape_occ_brep(shape, NULL, 0, &length), RMF_OK, "");
    char *text = malloc(length + 1);
    if (!text) {
        CHECK(0, "a buffer");
        return;
    }
    memset(text, 'x', length + 1);
    CHECK_STATUS(rmf_shape_occ_brep(shape, text, length, &again), RMF_ERROR_BUFFER_TOO_SMALL, "need");
    CHECK(again == length && text[0] == 'x', "too small: the length, no text");
    CHECK_STATUS(rmf_shape_occ_brep(shape, text, length + 1, &again), RMF_OK, "");
    CHECK(again == length && text[length] == 0 && strlen(text) == length, "the text and its NUL");
    size_t faces = 0;
    for (const char *at = text; (at = strstr(at, "\nFa\n")) != NULL; ++at) ++faces;
    RmfBrep *brep = NULL;
    RmfBrepCounts counts = {0};
    CHECK_STATUS(rmf_shape_brep(shape, &brep), RMF_OK, "");
    if (brep) CHECK_STATUS(rmf_brep_counts(brep, &counts), RMF_OK, "");
    rmf_brep_free(brep);
    CHECK(strstr(text, "CASCADE Topology V1, (c) Matra-Datavision\n") != NULL && faces == counts.face_count &&
              faces > 0,
          "the version line and one record per face");
    CHECK(length > 8 && strstr(text, "\nSo\n") != NULL && strcmp(text + length - 6, "\n+1 0\n") == 0,
          "a solid, the root last");
    CHECK_STATUS(rmf_shape_occ_brep(shape, text, 0, NULL), RMF_ERROR_NULL_POINTER, "length");
    CHECK_STATUS(rmf_shape_occ_brep(shape, NULL, 8, &again), RMF_ERROR_NULL_POINTER, "buffer");
    CHECK_STATUS(rmf_shape_occ_brep(NULL, NULL, 0, &again), RMF_ERROR_NULL_POINTER, "shape");
    free(text);
}

/* A little-endian 32-bit integer of a binary B-rep. */
static long le32(const unsigned char *at) {
    return (long)((uint32_t)at[0] | (uint32_t)at[1] << 8 | (uint32_t)at[2] << 16 | (uint32_t)at[3] << 24);
}

/* The binary B-rep of a shape for `reader`, malloc'ed (NULL on failure), its length in *length. */
static unsigned char *occ_binary(const RmfShape *shape, RmfOccReader reader, size_t *length) {
    CHECK_STATUS(rmf_shape_occ_binary(shape, reader, NULL, 0, length), RMF_OK, "");
    unsigned char *data = malloc(*length);
    if (!data) return NULL;
    size_t again = 0;
    CHECK_STATUS(rmf_shape_occ_binary(shape, reader, data, *length, &again), RMF_OK, "");
    CHECK(again == *length, "the length of a binary B-rep");
    return data;
}

/* OpenCascade's binary B-rep: size query, too small a buffer, the version line and the
   TShapes table, the root as BinTools::Read (orientation byte, number 1 from the last,
   location 0) and FreeCAD's importBinary (the root's number N, location 0, orientation 0)
   read it after the same set, the same file from the shape's B-rep, bad arguments. */
static void check_occ_binary(const RmfShape *shape) {
    size_t length = 0, freecad_length = 0, again = 0;
    unsigned char *data = occ_binary(shape, RMF_OCC_READER_BINTOOLS, &length);
    unsigned char *freecad = occ_binary(shape, RMF_OCC_READER_FREECAD, &freecad_length);
    if (!data || !freecad) {
        CHECK(0, "buffers");
        free(data);
        free(freecad);
        return;
    }
    unsigned char *small = malloc(length);
    if (small) {
        memset(small, 'x', length);
        CHECK_STATUS(rmf_shape_occ_binary(shape, RMF_OCC_READER_BINTOOLS, small, length - 1, &again),
                     RMF_ERROR_BUFFER_TOO_SMALL, "need");
        CHECK(again == length && small[0] == 'x', "too small: the length, nothing written");
        free(small);
    }
    static const char version[] = "\nOpen CASCADE Topology V3 (c)\nLocations 0\nCurve2ds ";
    CHECK(length > sizeof version && memcmp(data, version, sizeof version - 1) == 0, "the version line");
    CHECK(freecad_length == length + 3 && memcmp(data, freecad, length - 9) == 0,
          "the same set before either root");
    long shapes = -1;
    static const char table[] = "\nTShapes ";
    for (size_t i = 0; i + sizeof table < length; ++i) {
        if (memcmp(data + i, table, sizeof table - 1) == 0) shapes = strtol((const char *)data + i + 9, NULL, 10);
    }
    const unsigned char *root = data + length - 9, *freecad_root = freecad + freecad_length - 12;
    CHECK(shapes > 0 && root[0] == 0 && le32(root + 1) == 1 && le32(root + 5) == 0, "BinTools' root");
    CHECK(le32(freecad_root) == shapes && le32(freecad_root + 4) == 0 && le32(freecad_root + 8) == 0,
          "FreeCAD's root");
    RmfBrep *brep = NULL;
    CHECK_STATUS(rmf_shape_brep(shape, &brep), RMF_OK, "");
    if (brep) {
        unsigned char *same = malloc(length);
        size_t n = 0;
        CHECK_STATUS(rmf_brep_occ_binary(brep, RMF_OCC_READER_BINTOOLS, NULL, 0, &n), RMF_OK, "");
        if (same && n == length) {
            CHECK_STATUS(rmf_brep_occ_binary(brep, RMF_OCC_READER_BINTOOLS, same, n, &n), RMF_OK, "");
            CHECK(memcmp(same, data, length) == 0, "the shape's B-rep writes the same file");
        } else {
            CHECK(0, "the shape's B-rep has the file's length");
        }
        CHECK_STATUS(rmf_brep_occ_binary(brep, 7, NULL, 0, &n), RMF_ERROR_INVALID_INPUT, "reader");
        CHECK_STATUS(rmf_brep_occ_binary(NULL, RMF_OCC_READER_FREECAD, NULL, 0, &n), RMF_ERROR_NULL_POINTER,
                     "brep");
        free(same);
    }
    rmf_brep_free(brep);
    CHECK_STATUS(rmf_shape_occ_binary(shape, 2, NULL, 0, &again), RMF_ERROR_INVALID_INPUT, "reader = 2");
    CHECK_STATUS(rmf_shape_occ_binary(shape, RMF_OCC_READER_BINTOOLS, data, 0, NULL), RMF_ERROR_NULL_POINTER,
                 "length");
    CHECK_STATUS(rmf_shape_occ_binary(shape, RMF_OCC_READER_BINTOOLS, NULL, 8, &again),
                 RMF_ERROR_NULL_POINTER, "buffer");
    CHECK_STATUS(rmf_shape_occ_binary(NULL, RMF_OCC_READER_BINTOOLS, NULL, 0, &again),
                 RMF_ERROR_NULL_POINTER, "shape");
    free(data);
    free(freecad);
}

/* rmf_shape_volume: the library's own figure agrees with this suite's integration and
   with pi r^2 L; NULLs named, and a sheet (the same sweep, not solid) refused with nothing
   written. */
static void check_shape_volume(const RmfShape *shape, double exact, const RmfCurve *profile,
                               const RmfEdge *e) {
    double v = -1;
    CHECK_STATUS(rmf_shape_volume(shape, &v), RMF_OK, "");
    printf("rmf_shape_volume: %.15f (relative %.1e)\n", v, fabs(v - exact) / exact);
    CHECK(fabs(v - exact) <= 1e-12 * exact, "rmf_shape_volume is pi r^2 L");
    CHECK(fabs(v - volume(shape)) <= 1e-12 * exact, "rmf_shape_volume is the suite's volume");
    CHECK_STATUS(rmf_shape_volume(NULL, &v), RMF_ERROR_NULL_POINTER, "shape is NULL");
    CHECK_STATUS(rmf_shape_volume(shape, NULL), RMF_ERROR_NULL_POINTER, "out is NULL");
    RmfWireSweepOptions o;
    RmfShape *sheet = NULL;
    rmf_wire_sweep_options_init(&o);
    o.solid = 0;
    CHECK_STATUS(rmf_wire_sweep(e, 3, profile, NULL, 0, &o, &sheet), RMF_OK, "");
    if (!sheet) return;
    v = -1;
    CHECK_STATUS(rmf_shape_volume(sheet, &v), RMF_ERROR_INVALID_INPUT, "a sheet, not a solid");
    CHECK(v == -1, "a refused volume writes nothing");
    rmf_shape_free(sheet);
}

static void test_pipe_route(void) {
    RmfEdge e[3];
    RmfCurve *profile = circle(1), *hole = circle(0.8);
    RmfShape *shape = NULL, *hollow = NULL;
    RmfSweepReport report;
    double worst_radius = 0, worst_cos = 0;
    pipe_route(e);
    CHECK_STATUS(rmf_wire_sweep(e, 3, profile, NULL, 0, NULL, &shape), RMF_OK, "");
    if (!shape) return;
    CHECK(rmf_shape_is_solid(shape) == 1, "a closed solid");
    CHECK(rmf_shape_face_count(shape) == 14, "four quarters per edge, two caps");
    for (size_t f = 0; f < rmf_shape_face_count(shape); ++f) {
        RmfShapeFace face;
        RmfNurbsSurface view;
        CHECK_STATUS(rmf_shape_face(shape, f, &face), RMF_OK, "");
        if (face.kind != RMF_FACE_SWEPT) {
            CHECK(face.surface == NULL && face.loop_count == 1, "a cap with one loop");
            continue;
        }
        CHECK(face.spine_edge == f / 4 && face.profile_edge == f % 4 && face.reversed == 0, "faces in order");
        CHECK_STATUS(rmf_surface_nurbs(face.surface, &view), RMF_OK, "");
        CHECK(view.degree_v == (face.spine_edge == 1 ? 2u : 1u), "degree 1 along lines, 2 along the arc");
        for (int i = 0; i <= 8; ++i)
            for (int j = 0; j <= 8; ++j) {
                RmfVec3 d[3][3];
                double u = view.knots_u[0] + (view.knots_u[view.knot_count_u - 1] - view.knots_u[0]) * i / 8;
                double v = view.knots_v[0] + (view.knots_v[view.knot_count_v - 1] - view.knots_v[0]) * j / 8;
                ne_surface_derivatives(&view, u, v, d);
                worst_radius = fmax(worst_radius, fabs(from_spine(d[0][0]) - 1));
                worst_cos = fmax(worst_cos, ne_parameter_line_cosine(d));
            }
    }
    const double exact = PI * (20 + 2.5 * PI), v = volume(shape);
    printf("pipe route, circle r = 1: faces at distance 1 from the spine within %.1e, max |cos| %.1e, "
           "volume %.15f vs pi r^2 L %.15f (relative %.1e)\n",
           worst_radius, worst_cos, v, exact, fabs(v - exact) / exact);
    CHECK(worst_radius < 1e-14, "exact cylinders and torus");
    CHECK(worst_cos <= 1e-12, "orthogonal parameter lines on lines and arcs");
    CHECK(fabs(v - exact) <= 1e-12 * exact, "volume pi r^2 L");
    check_shape_volume(shape, exact, profile, e);
    CHECK_STATUS(rmf_shape_report(shape, &report), RMF_OK, "");
    CHECK(report.spine_distance == 0 && report.rmf_angle_error == 0 && report.face_count == 14, "exact spine");
    CHECK(report.max_parameter_cosine <= 1e-12 && report.singularity_margin > 0.79, "margin 1 - 1/5");
    CHECK(report.seam_gap == 0 && report.corner_turn == 0, "no closure, no corners");
    CHECK(report.joint_gap < 1e-13, "the faces meet at the joints");
    char path[512];
    snprintf(path, sizeof path, "%s/abi_wire_%ld.step", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp",
             (long)time(NULL) ^ (long)(uintptr_t)&path);
    CHECK_STATUS(rmf_shape_write_step(shape, path), RMF_OK, "");
    FILE *file = fopen(path, "r");
    CHECK(file != NULL, "the STEP file is written");
    if (file) {
        char line_text[4096];
        int solid = 0;
        while (fgets(line_text, sizeof line_text, file))
            if (strstr(line_text, "MANIFOLD_SOLID_BREP")) solid = 1;
        fclose(file);
        CHECK(solid, "a MANIFOLD_SOLID_BREP");
    }
    check_step_text_is_the_file(shape, path);
    remove(path);
    check_occ_brep_text(shape);
    check_occ_binary(shape);
    /* With a hole: the annulus. */
    const RmfCurve *holes[1] = {hole};
    CHECK_STATUS(rmf_wire_sweep(e, 3, profile, holes, 1, NULL, &hollow), RMF_OK, "");
    if (hollow) {
        const double annulus = PI * (1 - 0.64) * (20 + 2.5 * PI), vh = volume(hollow);
        CHECK(rmf_shape_face_count(hollow) == 26, "inner faces too");
        CHECK(fabs(vh - annulus) <= 1e-12 * annulus, "hollow pipe volume");
        for (size_t f = 0; f < rmf_shape_face_count(hollow); ++f) {
            RmfShapeFace face;
            CHECK_STATUS(rmf_shape_face(hollow, f, &face), RMF_OK, "");
            if (face.kind == RMF_FACE_SWEPT)
                CHECK(face.reversed == (face.profile_loop == 1), "inner faces point into the hole");
            else
                CHECK(face.loop_count == 2, "caps with a hole");
        }
    }
    rmf_shape_free(hollow);
    rmf_shape_free(shape);
    rmf_curve_free(hole);
    rmf_curve_free(profile);
}

/* Three right angles in 3-D, legs of 6; round (radius 1) and miter. */
static void test_corners(void) {
    RmfEdge e[4] = {line(vec3(0, 0, 0), vec3(6, 0, 0)), line(vec3(6, 0, 0), vec3(6, 6, 0)),
                    line(vec3(6, 6, 0), vec3(6, 6, 6)), line(vec3(6, 6, 6), vec3(0, 6, 6))};
    RmfCurve *profile = square(0.5);
    RmfWireSweepOptions o;
    rmf_wire_sweep_options_init(&o);
    for (int miter = 0; miter <= 1; ++miter) {
        RmfShape *shape = NULL;
        RmfSweepReport r;
        o.corner = miter ? RMF_CORNER_MITER : RMF_CORNER_ROUND;
        o.corner_radius = 1;
        CHECK_STATUS(rmf_wire_sweep(e, 4, profile, NULL, 0, &o, &shape), RMF_OK, "");
        if (!shape) continue;
        const double length = miter ? 24 : 24 - 3 * (2 - PI / 2), v = volume(shape);
        CHECK_STATUS(rmf_shape_report(shape, &r), RMF_OK, "");
        printf("polyline, three 90-degree corners, %s: volume %.15f vs %.15f (relative %.1e), frame turn across "
               "corners %.1e rad\n",
               miter ? "miter" : "round", v, length, fabs(v - length) / length, r.corner_turn);
        CHECK(fabs(v - length) <= 1e-12 * length, "volume of the square tube");
        CHECK(r.corner_turn <= 1e-12, "no turn about the tangent at corners");
        CHECK(rmf_shape_face_count(shape) == (miter ? 18u : 30u), "faces per leg (and elbow), two caps");
        rmf_shape_free(shape);
    }
    rmf_curve_free(profile);
}

/* A closed cubic NURBS (eight uniform spans of a periodic B-spline through a bent loop). */
static RmfCurve *closed_loop(void) {
    RmfVec3 c[8], p[25];
    double k[29];
    for (int i = 0; i < 8; ++i) {
        const double a = 2 * PI * i / 8;
        c[i] = vec3(4 * cos(a), 3 * sin(a), 1.5 * sin(2 * a));
    }
    for (int i = 0; i < 8; ++i) {
        RmfVec3 a = c[i], b = c[(i + 1) % 8], d = c[(i + 2) % 8], e = c[(i + 3) % 8];
        p[3 * i] = ne_scale(ne_add(ne_add(a, ne_scale(b, 4)), d), 1.0 / 6);
        p[3 * i + 1] = ne_scale(ne_add(ne_scale(b, 2), d), 1.0 / 3);
        p[3 * i + 2] = ne_scale(ne_add(b, ne_scale(d, 2)), 1.0 / 3);
        if (i == 7) p[24] = ne_scale(ne_add(ne_add(b, ne_scale(d, 4)), e), 1.0 / 6);
    }
    p[24] = p[0];
    for (int i = 0; i < 4; ++i) k[i] = 0, k[25 + i] = 8;
    for (int i = 1; i < 8; ++i) k[3 * i + 1] = k[3 * i + 2] = k[3 * i + 3] = i;
    return nurbs(3, p, NULL, 25, k);
}

static void test_closed_nurbs(void) {
    RmfCurve *loop = closed_loop(), *profile = square(0.3);
    RmfEdge e = {RMF_EDGE_CURVE, {vec3(0, 0, 0), vec3(0, 0, 0), vec3(0, 0, 0)}, loop};
    RmfWireSweepOptions o;
    RmfShape *shape = NULL;
    RmfSweepReport r;
    rmf_wire_sweep_options_init(&o);
    o.tolerance = 1e-5;
    o.closure_symmetry = 4;
    CHECK_STATUS(rmf_wire_sweep(&e, 1, profile, NULL, 0, &o, &shape), RMF_OK, "");
    if (shape) {
        CHECK_STATUS(rmf_shape_report(shape, &r), RMF_OK, "");
        printf("closed NURBS, square profile: seam gap %.1e, spine within %.1e of the NURBS, %zu faces\n", r.seam_gap,
               r.spine_distance, r.face_count);
        CHECK(rmf_shape_is_solid(shape) && r.face_count == 4, "a closed ring, no caps");
        CHECK(r.seam_gap <= 1e-12 && r.spine_distance <= 1e-5, "no seam, within the tolerance");
    }
    rmf_shape_free(shape);
    rmf_curve_free(profile);
    rmf_curve_free(loop);
}

static RmfShape *sentinel(void) { return (RmfShape *)(uintptr_t)0x5e5e; }

/* A failing call leaves *out untouched. */
#define REFUSED(call_with_out, status, mention)                                                   \
    do {                                                                                          \
        RmfShape *out = sentinel();                                                               \
        CHECK_STATUS(call_with_out, status, mention);                                             \
        CHECK(out == sentinel(), "out untouched on failure");                                     \
    } while (0)

/* The options of a program built against the header before frame and scale (struct_size up
   to solid): accepted, the fields it does not know keep their defaults (whatever lies after
   its struct is not read), the same shape as with the defaults. */
static void test_options_of_an_older_header(void) {
    RmfEdge e[3];
    RmfCurve *profile = circle(1);
    RmfWireSweepOptions o;
    RmfShape *shape = NULL;
    pipe_route(e);
    rmf_wire_sweep_options_init(&o);
    o.struct_size = offsetof(RmfWireSweepOptions, frame);
    o.frame = 77, o.scale_start = -1, o.scale_end = nan_value(); /* not the caller's: ignored */
    CHECK(o.struct_size == 80, "the struct of 0.2 before frame and scale is 80 bytes");
    CHECK_STATUS(rmf_wire_sweep(e, 3, profile, NULL, 0, &o, &shape), RMF_OK, "");
    if (shape) {
        const double exact = PI * (20 + 2.5 * PI), v = volume(shape);
        CHECK(fabs(v - exact) <= 1e-12 * exact, "the default sweep");
    }
    rmf_shape_free(shape);
    /* The header of frame and scale, before method: the PH cubic spline's RMF. */
    o.struct_size = offsetof(RmfWireSweepOptions, method);
    o.frame = RMF_FRAME_RMF, o.scale_start = 1, o.scale_end = 1, o.method = 77; /* not read */
    CHECK(o.struct_size == 128, "the struct of 0.2 before method is 128 bytes");
    CHECK_STATUS(rmf_wire_sweep(e, 3, profile, NULL, 0, &o, &shape), RMF_OK, "");
    rmf_shape_free(shape);
    shape = NULL;
    /* The header of method, before scale_knots: no knots, whatever lies after its struct. */
    o.struct_size = offsetof(RmfWireSweepOptions, scale_knots);
    o.method = RMF_SPINE_PH_RMF, o.scale_knots = NULL, o.scale_knot_count = 3; /* not read */
    CHECK(o.struct_size == 136, "the struct of 0.2 before scale_knots is 136 bytes");
    CHECK_STATUS(rmf_wire_sweep(e, 3, profile, NULL, 0, &o, &shape), RMF_OK, "");
    if (shape) {
        const double exact = PI * (20 + 2.5 * PI), v = volume(shape);
        CHECK(fabs(v - exact) <= 1e-12 * exact, "the default sweep: the knots not read");
    }
    rmf_shape_free(shape);
    shape = NULL;
    /* The header of scale_knots, before the guide: its fields are not read. */
    o.struct_size = offsetof(RmfWireSweepOptions, guide_edges);
    o.scale_knot_count = 0;
    o.guide_edges = (const RmfEdge *)(uintptr_t)0x5e5e, o.guide_edge_count = 7;
    CHECK(o.struct_size == 152, "the struct of 0.2 before the guide is 152 bytes");
    CHECK_STATUS(rmf_wire_sweep(e, 3, profile, NULL, 0, &o, &shape), RMF_OK, "");
    if (shape) {
        const double exact = PI * (20 + 2.5 * PI), v = volume(shape);
        CHECK(fabs(v - exact) <= 1e-12 * exact, "the default sweep: the guide not read");
    }
    rmf_shape_free(shape);
    shape = NULL;
    o.struct_size = offsetof(RmfWireSweepOptions, frame) - 8;
    REFUSED(rmf_wire_sweep(e, 3, profile, NULL, 0, &o, &out), RMF_ERROR_INVALID_INPUT,
            "options->struct_size = 72 is no size of this struct (80 to");
    rmf_curve_free(profile);
}

/* The scale law along a straight line (intended behaviour of the geometry): a circle of
   radius 1 at the start, scale [1, 0.5], length 3, is the frustum of volume
   pi L (r0^2 + r0 r1 + r1^2) / 3; the report's frame_error is 0 for the RMF. Then each frame
   on the same line: the volume does not depend on how the circle turns. */
static void test_scale_law_frustum(void) {
    RmfEdge e = line(vec3(0, 0, 0), vec3(3, 0, 0));
    RmfCurve *profile = circle(1);
    RmfWireSweepOptions o;
    const double r0 = 1, r1 = 0.5, length = 3, exact = PI * length * (r0 * r0 + r0 * r1 + r1 * r1) / 3;
    const RmfSweepFrame frames[3] = {RMF_FRAME_RMF, RMF_FRAME_FRENET, RMF_FRAME_FIXED};
    for (int k = 0; k < 3; ++k) {
        RmfShape *shape = NULL;
        RmfSweepReport r;
        rmf_wire_sweep_options_init(&o);
        o.scale_start = 1, o.scale_end = 0.5;
        o.frame = frames[k];
        if (frames[k] == RMF_FRAME_FIXED) o.frame_direction = vec3(0, 0, 1);
        CHECK_STATUS(rmf_wire_sweep(&e, 1, profile, NULL, 0, &o, &shape), RMF_OK, "");
        if (!shape) continue;
        const double v = volume(shape);
        CHECK_STATUS(rmf_shape_report(shape, &r), RMF_OK, "");
        printf("frustum along a line, scale [1, 0.5], frame %d: volume %.15f vs %.15f (relative %.1e), frame "
               "error %.1e\n",
               (int)frames[k], v, exact, fabs(v - exact) / exact, r.frame_error);
        CHECK(rmf_shape_is_solid(shape) == 1, "a closed solid");
        CHECK(fabs(v - exact) <= 1e-12 * exact, "the frustum's volume pi L (r0^2 + r0 r1 + r1^2) / 3");
        CHECK(r.frame_error >= 0 && r.frame_error <= 1e-12, "the frame asked for");
        rmf_shape_free(shape);
    }
    rmf_curve_free(profile);
}

/* The knots of the scale law along a straight line (intended behaviour of the geometry): a
   circle of radius r along a line of length L, scale [1, 1] through the knots (0.25, 2) and
   (0.75, 0.5), is the chain of frustums of lengths L/4, L/2, L/4 between the scales 1, 2, 0.5,
   1: volume pi r^2 sum L_i (a^2 + a b + b^2) / 3, by this suite's own integration. Then the
   same with scale [0.5, 1.5] through one knot (0.4, 1); the first law without its knots is
   the cylinder (the check can fail). */
static void test_scale_knots_frustums(void) {
    const double r = 0.75, length = 4;
    RmfEdge e = line(vec3(0, 0, 0), vec3(length, 0, 0));
    RmfCurve *profile = circle(r);
    const double two_knots[4] = {0.25, 2, 0.75, 0.5}, one_knot[2] = {0.4, 1};
    struct {
        double start, end;
        const double *knots;
        size_t count;
    } laws[2] = {{1, 1, two_knots, 2}, {0.5, 1.5, one_knot, 1}};
    for (int k = 0; k < 2; ++k) {
        RmfWireSweepOptions o;
        RmfShape *shape = NULL;
        double exact = 0, at = 0, a = laws[k].start;
        for (size_t i = 0; i <= laws[k].count; ++i) {
            const double next = i < laws[k].count ? laws[k].knots[2 * i] : 1;
            const double b = i < laws[k].count ? laws[k].knots[2 * i + 1] : laws[k].end;
            exact += PI * r * r * (next - at) * length * (a * a + a * b + b * b) / 3;
            at = next, a = b;
        }
        rmf_wire_sweep_options_init(&o);
        o.scale_start = laws[k].start, o.scale_end = laws[k].end;
        o.scale_knots = laws[k].knots, o.scale_knot_count = laws[k].count;
        CHECK_STATUS(rmf_wire_sweep(&e, 1, profile, NULL, 0, &o, &shape), RMF_OK, "");
        if (!shape) continue;
        const double v = volume(shape);
        printf("chain of frustums along a line, scale [%g, %g] through %zu knot(s): volume %.15f vs %.15f "
               "(relative %.1e)\n",
               laws[k].start, laws[k].end, laws[k].count, v, exact, fabs(v - exact) / exact);
        CHECK(rmf_shape_is_solid(shape) == 1, "a closed solid");
        CHECK(fabs(v - exact) <= 1e-12 * exact, "the chain of frustums pi r^2 sum L_i (a^2 + a b + b^2) / 3");
        rmf_shape_free(shape);
        /* Without its knots the first law is the cylinder: the volumes differ. */
        if (k == 0) {
            o.scale_knot_count = 0;
            CHECK_STATUS(rmf_wire_sweep(&e, 1, profile, NULL, 0, &o, &shape), RMF_OK, "");
            if (shape) CHECK(fabs(volume(shape) - exact) > 0.1 * exact, "the knots change the volume");
            rmf_shape_free(shape);
        }
    }
    rmf_curve_free(profile);
}

/* The degree along the spine of the first lateral face along wire edge `edge` (0 if none). */
static uint32_t spine_degree(const RmfShape *shape, size_t edge) {
    for (size_t i = 0; i < rmf_shape_face_count(shape); ++i) {
        RmfShapeFace face;
        RmfNurbsSurface view;
        if (rmf_shape_face(shape, i, &face) != RMF_OK || face.kind != RMF_FACE_SWEPT || face.spine_edge != edge)
            continue;
        if (rmf_surface_nurbs(face.surface, &view) != RMF_OK) return 0;
        return (uint32_t)view.degree_v;
    }
    return 0;
}

/* A round profile along a curve edge (a line into the twisted cubic, a circle of radius
   0.05): RMF_PIPE_FRAME_LIGHTEST sweeps it on the PH spline's Euler-Rodrigues frame,
   faces of degree 5 along the spine against the RMF's 9, the same tube (volume to 1e-12);
   a square keeps degree 9 either way; a pipe_frame that is no RmfPipeFrame is refused
   naming it. */
static void test_pipe_frame(void) {
    const RmfVec3 poles[4] = {vec3(0, 0, 0), vec3(1.0 / 3, 0, 0), vec3(2.0 / 3, 1.0 / 3, 0), vec3(1, 1, 1)};
    const double knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
    RmfCurve *cubic = nurbs(3, poles, NULL, 4, knots), *round = circle(0.05), *square = NULL;
    const RmfVec3 corners[4] = {vec3(-0.04, -0.04, 0), vec3(0.04, -0.04, 0), vec3(0.04, 0.04, 0), vec3(-0.04, 0.04, 0)};
    CHECK_STATUS(rmf_curve_polygon(corners, 4, &square), RMF_OK, "");
    RmfEdge e[2] = {line(vec3(-1, 0, 0), vec3(0, 0, 0)),
                    {RMF_EDGE_CURVE, {vec3(0, 0, 0), vec3(0, 0, 0), vec3(0, 0, 0)}, NULL}};
    e[1].curve = cubic;
    RmfShape *shapes[4] = {NULL, NULL, NULL, NULL};
    for (int k = 0; k < 4; ++k) {
        RmfWireSweepOptions o;
        rmf_wire_sweep_options_init(&o);
        CHECK(o.pipe_frame == RMF_PIPE_FRAME_RMF, "the RMF by default");
        o.tolerance = 1e-5;
        o.pipe_frame = k % 2 ? RMF_PIPE_FRAME_LIGHTEST : RMF_PIPE_FRAME_RMF;
        CHECK_STATUS(rmf_wire_sweep(e, 2, k < 2 ? round : square, NULL, 0, &o, &shapes[k]), RMF_OK, "");
    }
    if (shapes[0] && shapes[1] && shapes[2] && shapes[3]) {
        const double rmf = volume(shapes[0]), light = volume(shapes[1]);
        printf("circle along the twisted cubic: degree along the spine %u (RMF %u), volume %.15f (RMF %.15f)\n",
               spine_degree(shapes[1], 1), spine_degree(shapes[0], 1), light, rmf);
        CHECK(spine_degree(shapes[0], 1) == 9 && spine_degree(shapes[1], 1) == 5, "degree 5 on the lightest frame");
        CHECK(fabs(light - rmf) <= 1e-12 * rmf, "the same tube");
        CHECK(spine_degree(shapes[2], 1) == 9 && spine_degree(shapes[3], 1) == 9, "a square keeps the RMF");
    }
    RmfWireSweepOptions bad;
    rmf_wire_sweep_options_init(&bad);
    bad.pipe_frame = 7;
    RmfShape *none = NULL;
    CHECK_STATUS(rmf_wire_sweep(e, 2, round, NULL, 0, &bad, &none), RMF_ERROR_INVALID_INPUT, "options->pipe_frame = 7");
    CHECK(none == NULL, "nothing written");
    /* A caller built against the header before pipe_frame passes the struct up to
       guide_edge_count: its pipe_frame is not read (the RMF). */
    CHECK(offsetof(RmfWireSweepOptions, pipe_frame) == 168, "pipe_frame follows guide_edge_count at 168 bytes");
    bad.struct_size = offsetof(RmfWireSweepOptions, pipe_frame);
    CHECK_STATUS(rmf_wire_sweep(e, 2, round, NULL, 0, &bad, &none), RMF_OK, "");
    CHECK(none && spine_degree(none, 1) == 9, "an older header's options: the RMF");
    rmf_shape_free(none);
    for (int k = 0; k < 4; ++k) rmf_shape_free(shapes[k]);
    rmf_curve_free(cubic);
    rmf_curve_free(round);
    rmf_curve_free(square);
}

/* The spine method on a curve edge (intended behaviour of the geometry): a line into the
   twisted cubic (t, t^2, t^3), tangent to it, with a circle of radius 0.05. The PH cubic
   spline's rational RMF leaves its parameter lines off orthogonal by more than 1e-10; the
   Moebius and RRMF spines carry exact rational RMFs, orthogonal to rounding (< 1e-12). Each
   spine within its tolerance, each shape a closed solid whose volume agrees with the
   ph-rmf one's to the tolerances. */
static void test_spine_methods(void) {
    const RmfVec3 poles[4] = {vec3(0, 0, 0), vec3(1.0 / 3, 0, 0), vec3(2.0 / 3, 1.0 / 3, 0), vec3(1, 1, 1)};
    const double knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
    RmfCurve *cubic = nurbs(3, poles, NULL, 4, knots), *profile = circle(0.05);
    RmfEdge e[2] = {line(vec3(-1, 0, 0), vec3(0, 0, 0)),
                    {RMF_EDGE_CURVE, {vec3(0, 0, 0), vec3(0, 0, 0), vec3(0, 0, 0)}, NULL}};
    const uint32_t methods[3] = {RMF_SPINE_PH_RMF, RMF_SPINE_MOBIUS, RMF_SPINE_RRMF};
    const double tolerances[3] = {1e-5, 1e-5, 1e-4};
    double cosines[3] = {0, 1, 1}, volumes[3] = {0, 0, 0};
    e[1].curve = cubic;
    for (int k = 0; k < 3; ++k) {
        RmfWireSweepOptions o;
        RmfShape *shape = NULL;
        RmfSweepReport r;
        rmf_wire_sweep_options_init(&o);
        o.method = methods[k];
        o.tolerance = tolerances[k];
        CHECK_STATUS(rmf_wire_sweep(e, 2, profile, NULL, 0, &o, &shape), RMF_OK, "");
        if (!shape) continue;
        CHECK_STATUS(rmf_shape_report(shape, &r), RMF_OK, "");
        cosines[k] = r.max_parameter_cosine;
        volumes[k] = volume(shape);
        printf("line into the twisted cubic, method %u: max |cos| %.1e, spine within %.1e, volume %.15f\n",
               (unsigned)methods[k], r.max_parameter_cosine, r.spine_distance, volumes[k]);
        CHECK(rmf_shape_is_solid(shape) == 1, "a closed solid");
        CHECK(r.spine_distance <= tolerances[k], "the spine within the tolerance");
        rmf_shape_free(shape);
    }
    CHECK(cosines[0] > 1e-10, "the PH cubic spline's rational RMF: parameter lines off orthogonal by > 1e-10");
    CHECK(cosines[1] < 1e-12, "the Moebius spine's exact RMF: parameter lines orthogonal to rounding");
    CHECK(cosines[2] < 1e-12, "the RRMF spine's exact RMF: parameter lines orthogonal to rounding");
    /* pi r^2 times lengths that differ by the spines' distances from the cubic. */
    CHECK(fabs(volumes[1] - volumes[0]) <= 1e-6 * volumes[0] && fabs(volumes[2] - volumes[0]) <= 1e-5 * volumes[0],
          "the same tube");
    rmf_curve_free(profile);
    rmf_curve_free(cubic);
}

/* The helix (2 cos t, 2 sin t, pitch t / 2pi) as a callback; user points to the pitch. */
static void guide_helix(double t, void *user, RmfVec3 *point, RmfVec3 *tangent) {
    const double rise = *(const double *)user / (2 * PI);
    *point = vec3(2 * cos(t), 2 * sin(t), rise * t);
    *tangent = vec3(-2 * sin(t), 2 * cos(t), rise);
}

/* The guide frame (intended behaviour of the geometry): a triangle with a vertex at 0.5 on
   f2, swept along the z axis (a line of 4) with the helix of radius 2 and pitch 2 about it
   as the guide (a PH spline within 1e-8 of it, an RMF_EDGE_CURVE edge). f2 points at the
   guide's crossing of each normal plane z = const, the helix's point at angle 2 pi z /
   pitch: the vertex runs along the helix (0.5 cos, 0.5 sin, z) of the same pitch, measured
   here on every swept face that starts at radius 0.5; the RMF of the line does not turn
   (the vertex stays at (0.5, 0, z), off that helix). The prism's volume is the
   triangle's area times the length either way. Then the guide's bad inputs: NULL, a count
   of 0, a point that is not finite, each refused with *out untouched. */
static void test_guide_frame(void) {
    double pitch = 2, d = 0;
    const RmfVec3 corners[4] = {vec3(0.5, 0, 0), vec3(-0.2, 0.3, 0), vec3(-0.2, -0.3, 0), vec3(0.5, 0, 0)};
    const double k[6] = {0, 0, 1, 2, 3, 3};
    RmfCurve *helix = NULL, *profile = nurbs(1, corners, NULL, 4, k);
    RmfEdge bar = line(vec3(0, 0, 0), vec3(0, 0, 4));
    RmfEdge guide = {RMF_EDGE_CURVE, {vec3(0, 0, 0), vec3(0, 0, 0), vec3(0, 0, 0)}, NULL};
    double off[2] = {0, 0};
    int tracked[2] = {0, 0};
    CHECK_STATUS(rmf_ph_spline_approximate(NULL, guide_helix, &pitch, 0, 4 * PI, 1e-8, &helix, &d), RMF_OK, "");
    guide.curve = helix;
    for (int guided = 0; guided <= 1; ++guided) {
        RmfWireSweepOptions o;
        RmfShape *shape = NULL;
        RmfSweepReport r;
        rmf_wire_sweep_options_init(&o);
        o.tolerance = 1e-6;
        if (guided) o.frame = RMF_FRAME_GUIDE, o.guide_edges = &guide, o.guide_edge_count = 1;
        CHECK_STATUS(rmf_wire_sweep(&bar, 1, profile, NULL, 0, &o, &shape), RMF_OK, "");
        if (!shape) continue;
        for (size_t f = 0; f < rmf_shape_face_count(shape); ++f) {
            RmfShapeFace face;
            RmfNurbsSurface view;
            CHECK_STATUS(rmf_shape_face(shape, f, &face), RMF_OK, "");
            if (face.kind != RMF_FACE_SWEPT) continue;
            CHECK_STATUS(rmf_surface_nurbs(face.surface, &view), RMF_OK, "");
            const double u0 = view.knots_u[0], v0 = view.knots_v[0], v1 = view.knots_v[view.knot_count_v - 1];
            RmfVec3 d0[3][3];
            ne_surface_derivatives(&view, u0, v0, d0);
            if (fabs(hypot(d0[0][0].x, d0[0][0].y) - 0.5) > 1e-9) continue; /* another vertex */
            ++tracked[guided];
            for (int j = 0; j <= 400; ++j) {
                RmfVec3 dd[3][3];
                ne_surface_derivatives(&view, u0, v0 + (v1 - v0) * j / 400, dd);
                const RmfVec3 p = dd[0][0];
                const double a = 2 * PI * p.z / pitch;
                off[guided] = fmax(off[guided], ne_norm(ne_sub(p, vec3(0.5 * cos(a), 0.5 * sin(a), p.z))));
            }
        }
        const double v = volume(shape), exact = 0.5 * 0.6 * 0.7 * 4;
        CHECK_STATUS(rmf_shape_report(shape, &r), RMF_OK, "");
        printf("triangle along a line of 4, %s: the f2 vertex off the helix of radius 0.5, pitch 2 by %.1e "
               "(%d faces), volume %.15f vs %.15f (relative %.1e), frame error %.1e\n",
               guided ? "helical guide (RMF_FRAME_GUIDE)" : "the RMF", off[guided], tracked[guided], v, exact,
               fabs(v - exact) / exact, r.frame_error);
        CHECK(rmf_shape_is_solid(shape) == 1, "a closed solid");
        CHECK(fabs(v - exact) <= 1e-12 * exact, "the prism's volume: the triangle's area times the length");
        rmf_shape_free(shape);
    }
    CHECK(tracked[1] >= 1 && off[1] < 1e-6, "the f2 vertex on the helix of the guide's pitch (within 1e-6)");
    CHECK(tracked[0] >= 1 && off[0] > 0.1, "the RMF of a line does not turn: the check can fail");
    {
        RmfWireSweepOptions o;
        RmfEdge bad = line(vec3(2, 0, 0), vec3(2, 0, 4));
        rmf_wire_sweep_options_init(&o);
        o.frame = RMF_FRAME_GUIDE;
        REFUSED(rmf_wire_sweep(&bar, 1, profile, NULL, 0, &o, &out), RMF_ERROR_INVALID_INPUT,
                "options->guide_edge_count = 0: RMF_FRAME_GUIDE needs the guide's edges in options->guide_edges");
        o.guide_edge_count = 1;
        REFUSED(rmf_wire_sweep(&bar, 1, profile, NULL, 0, &o, &out), RMF_ERROR_NULL_POINTER,
                "options->guide_edges is NULL");
        o.guide_edges = &bad;
        o.guide_edge_count = 0;
        REFUSED(rmf_wire_sweep(&bar, 1, profile, NULL, 0, &o, &out), RMF_ERROR_INVALID_INPUT,
                "options->guide_edges");
        o.guide_edge_count = 1;
        bad.points[1].z = nan_value();
        REFUSED(rmf_wire_sweep(&bar, 1, profile, NULL, 0, &o, &out), RMF_ERROR_INVALID_INPUT,
                "options->guide_edges[0].points[1]");
        /* A guide along the first quarter of the wire only: the library's refusal, on the guide. */
        bad = line(vec3(2, 0, 0), vec3(2, 0, 1));
        REFUSED(rmf_wire_sweep(&bar, 1, profile, NULL, 0, &o, &out), RMF_ERROR_INVALID_INPUT,
                "options->frame = RMF_FRAME_GUIDE, options->guide_edges: the guide does not run beside the wire");
    }
    rmf_curve_free(profile);
    rmf_curve_free(helix);
}

static void test_bad_inputs(void) {
    RmfEdge e[3], bad[3];
    RmfCurve *profile = circle(1), *small = circle(0.1), *sq = square(0.5);
    const double open_knots[5] = {0, 0, 1, 2, 2};
    const RmfVec3 open_poles[3] = {vec3(0, 0, 0), vec3(1, 0, 0), vec3(1, 1, 0)};
    RmfCurve *open = nurbs(1, open_poles, NULL, 3, open_knots);
    const RmfCurve *holes[1] = {small}, *null_hole[1] = {NULL};
    RmfWireSweepOptions o;
    pipe_route(e);
    rmf_wire_sweep_options_init(&o);

    REFUSED(rmf_wire_sweep(NULL, 3, profile, NULL, 0, NULL, &out), RMF_ERROR_NULL_POINTER, "edges");
    REFUSED(rmf_wire_sweep(e, 0, profile, NULL, 0, NULL, &out), RMF_ERROR_INVALID_INPUT, "edge_count");
    REFUSED(rmf_wire_sweep(e, 3, NULL, NULL, 0, NULL, &out), RMF_ERROR_NULL_POINTER, "profile");
    REFUSED(rmf_wire_sweep(e, 3, profile, NULL, 1, NULL, &out), RMF_ERROR_NULL_POINTER, "holes");
    REFUSED(rmf_wire_sweep(e, 3, profile, null_hole, 1, NULL, &out), RMF_ERROR_INVALID_INPUT, "holes[0]");
    CHECK_STATUS(rmf_wire_sweep(e, 3, profile, NULL, 0, NULL, NULL), RMF_ERROR_NULL_POINTER, "out");

    memcpy(bad, e, sizeof bad);
    bad[1].kind = 7;
    REFUSED(rmf_wire_sweep(bad, 3, profile, NULL, 0, NULL, &out), RMF_ERROR_INVALID_INPUT, "edges[1].kind");
    memcpy(bad, e, sizeof bad);
    bad[2].points[1].y = nan_value();
    REFUSED(rmf_wire_sweep(bad, 3, profile, NULL, 0, NULL, &out), RMF_ERROR_INVALID_INPUT, "edges[2].points[1]");
    memcpy(bad, e, sizeof bad);
    bad[1].kind = RMF_EDGE_CURVE;
    REFUSED(rmf_wire_sweep(bad, 3, profile, NULL, 0, NULL, &out), RMF_ERROR_INVALID_INPUT, "edges[1].curve");
    /* Disconnected: the third edge starts 0.5 away, the gap in the message. */
    memcpy(bad, e, sizeof bad);
    bad[2].points[0].y = 5.5;
    REFUSED(rmf_wire_sweep(bad, 3, profile, NULL, 0, NULL, &out), RMF_ERROR_INVALID_INPUT,
            "edges 1 and 2 do not meet: the nearest ends are 5.000e-1 apart");
    /* Zero length. */
    memcpy(bad, e, sizeof bad);
    bad[2].points[1] = bad[2].points[0];
    REFUSED(rmf_wire_sweep(bad, 3, profile, NULL, 0, NULL, &out), RMF_ERROR_INVALID_INPUT,
            "edge 2: a line of zero length");
    /* A 180° reversal at a joint. */
    memcpy(bad, e, sizeof bad);
    bad[1] = line(vec3(10, 0, 0), vec3(5, 0, 0));
    REFUSED(rmf_wire_sweep(bad, 2, profile, NULL, 0, NULL, &out), RMF_ERROR_INVALID_INPUT,
            "joint between edges 0 and 1: the wire turns back on itself");
    /* Profiles: open for a solid, open with holes. */
    REFUSED(rmf_wire_sweep(e, 3, open, NULL, 0, NULL, &out), RMF_ERROR_INVALID_INPUT,
            "a solid needs a closed profile");
    o.solid = 0;
    REFUSED(rmf_wire_sweep(e, 3, open, holes, 1, &o, &out), RMF_ERROR_INVALID_INPUT, "holes need a closed");
    o.solid = 2;
    REFUSED(rmf_wire_sweep(e, 3, profile, NULL, 0, &o, &out), RMF_ERROR_INVALID_INPUT, "options->solid");
    rmf_wire_sweep_options_init(&o);
    /* The profile reaches past the arc's centre (radius 5): refused with the largest reach. */
    {
        RmfCurve *big = circle(6);
        REFUSED(rmf_wire_sweep(e, 3, big, NULL, 0, NULL, &out), RMF_ERROR_INVALID_INPUT,
                "edge 1: the arc's radius 4.99999");
        rmf_curve_free(big);
    }
    /* Corners: a radius that does not fit, one below the profile's extent, miters on arcs. */
    {
        RmfEdge poly[3] = {line(vec3(0, 0, 0), vec3(4, 0, 0)), line(vec3(4, 0, 0), vec3(4, 2, 0)),
                           line(vec3(4, 2, 0), vec3(0, 2, 0))};
        RmfEdge with_arc[2] = {line(vec3(-2, 4, 0), vec3(0, 2, 0)),
                               arc(vec3(0, 2, 0), vec3(sqrt(2.0), sqrt(2.0), 0), vec3(2, 0, 0))};
        RmfCurve *tiny = square(0.1);
        o.corner_radius = 1.5;
        REFUSED(rmf_wire_sweep(poly, 3, tiny, NULL, 0, &o, &out), RMF_ERROR_INVALID_INPUT,
                "the largest radius that fits every corner is 0.99999");
        o.corner_radius = 0.05;
        REFUSED(rmf_wire_sweep(poly, 3, tiny, NULL, 0, &o, &out), RMF_ERROR_INVALID_INPUT, "smallest radius allowed");
        o.corner_radius = -1;
        REFUSED(rmf_wire_sweep(poly, 3, tiny, NULL, 0, &o, &out), RMF_ERROR_INVALID_INPUT, "options->corner_radius");
        o.corner_radius = 0;
        o.corner = RMF_CORNER_MITER;
        REFUSED(rmf_wire_sweep(with_arc, 2, tiny, NULL, 0, &o, &out), RMF_ERROR_INVALID_INPUT,
                "a miter corner needs straight legs, but edge 1 is an arc");
        o.corner = 9;
        REFUSED(rmf_wire_sweep(poly, 3, tiny, NULL, 0, &o, &out), RMF_ERROR_INVALID_INPUT, "options->corner");
        rmf_wire_sweep_options_init(&o);
        o.struct_size = 3;
        REFUSED(rmf_wire_sweep(poly, 3, tiny, NULL, 0, &o, &out), RMF_ERROR_INVALID_INPUT, "struct_size");
        /* The frame and the scale law: each bad field named. */
        rmf_wire_sweep_options_init(&o);
        o.frame = 4;
        REFUSED(rmf_wire_sweep(poly, 3, tiny, NULL, 0, &o, &out), RMF_ERROR_INVALID_INPUT,
                "options->frame = 4 is no RmfSweepFrame");
        o.frame = RMF_FRAME_FIXED;
        REFUSED(rmf_wire_sweep(poly, 3, tiny, NULL, 0, &o, &out), RMF_ERROR_INVALID_INPUT,
                "options->frame_direction");
        o.frame_direction = vec3(0, nan_value(), 1);
        REFUSED(rmf_wire_sweep(poly, 3, tiny, NULL, 0, &o, &out), RMF_ERROR_INVALID_INPUT,
                "options->frame_direction");
        o.frame_direction = vec3(0, 0, 1);
        o.initial_normal = vec3(0, 0, 1);
        REFUSED(rmf_wire_sweep(poly, 3, tiny, NULL, 0, &o, &out), RMF_ERROR_INVALID_INPUT,
                "options->initial_normal");
        o.frame = RMF_FRAME_FRENET;
        REFUSED(rmf_wire_sweep(poly, 3, tiny, NULL, 0, &o, &out), RMF_ERROR_INVALID_INPUT,
                "options->initial_normal");
        rmf_wire_sweep_options_init(&o);
        o.scale_start = 0;
        REFUSED(rmf_wire_sweep(poly, 3, tiny, NULL, 0, &o, &out), RMF_ERROR_INVALID_INPUT,
                "options->scale_start = 0");
        o.scale_start = -2;
        REFUSED(rmf_wire_sweep(poly, 3, tiny, NULL, 0, &o, &out), RMF_ERROR_INVALID_INPUT,
                "options->scale_start = -2");
        o.scale_start = 1;
        o.scale_end = nan_value();
        REFUSED(rmf_wire_sweep(poly, 3, tiny, NULL, 0, &o, &out), RMF_ERROR_INVALID_INPUT,
                "options->scale_end = NaN");
        o.scale_end = HUGE_VAL;
        REFUSED(rmf_wire_sweep(poly, 3, tiny, NULL, 0, &o, &out), RMF_ERROR_INVALID_INPUT,
                "options->scale_end = inf");
        /* The spine method: unknown codes, the Frenet frame (options->frame's), and a scale law
           with the exact-RMF methods, each refused naming options->method. */
        rmf_wire_sweep_options_init(&o);
        o.method = 4;
        REFUSED(rmf_wire_sweep(poly, 3, tiny, NULL, 0, &o, &out), RMF_ERROR_INVALID_INPUT,
                "options->method = 4 is no method of a wire sweep");
        o.method = RMF_SPINE_FRENET;
        REFUSED(rmf_wire_sweep(poly, 3, tiny, NULL, 0, &o, &out), RMF_ERROR_INVALID_INPUT,
                "options->method = 1: frenet makes Frenet frames");
        o.method = RMF_SPINE_RRMF;
        o.scale_end = 2;
        REFUSED(rmf_wire_sweep(poly, 3, tiny, NULL, 0, &o, &out), RMF_ERROR_INVALID_INPUT,
                "options->method = 3: a scale law is exact along PH splines");
        /* The knots of the scale law: NULL with a count, a fraction out of (0, 1) or not
           after the one before, a scale not positive, each refused naming the double; a
           knot that makes the law non-constant with an exact-RMF method names the knots. */
        {
            const double outside[2] = {1.0, 2}, zero[2] = {0.0, 2}, decreasing[4] = {0.5, 2, 0.25, 1},
                         negative[4] = {0.25, 2, 0.5, -1}, not_a_number[2] = {0.5, 0}, tame[2] = {0.5, 2};
            double nan_scale[2] = {0.5, 0};
            nan_scale[1] = nan_value();
            rmf_wire_sweep_options_init(&o);
            o.scale_knot_count = 1;
            REFUSED(rmf_wire_sweep(poly, 3, tiny, NULL, 0, &o, &out), RMF_ERROR_NULL_POINTER,
                    "options->scale_knots is NULL");
            o.scale_knots = outside;
            REFUSED(rmf_wire_sweep(poly, 3, tiny, NULL, 0, &o, &out), RMF_ERROR_INVALID_INPUT,
                    "options->scale_knots[0] (the fraction of knot 0): its fraction of the wire's length 1 must "
                    "lie in (0, 1)");
            o.scale_knots = zero;
            REFUSED(rmf_wire_sweep(poly, 3, tiny, NULL, 0, &o, &out), RMF_ERROR_INVALID_INPUT,
                    "options->scale_knots[0] (the fraction of knot 0)");
            o.scale_knots = decreasing, o.scale_knot_count = 2;
            REFUSED(rmf_wire_sweep(poly, 3, tiny, NULL, 0, &o, &out), RMF_ERROR_INVALID_INPUT,
                    "options->scale_knots[2] (the fraction of knot 1)");
            o.scale_knots = negative;
            REFUSED(rmf_wire_sweep(poly, 3, tiny, NULL, 0, &o, &out), RMF_ERROR_INVALID_INPUT,
                    "options->scale_knots[3] (the scale of knot 1): the scale -1 must be finite and positive");
            o.scale_knots = not_a_number, o.scale_knot_count = 1;
            REFUSED(rmf_wire_sweep(poly, 3, tiny, NULL, 0, &o, &out), RMF_ERROR_INVALID_INPUT,
                    "options->scale_knots[1] (the scale of knot 0): the scale 0");
            o.scale_knots = nan_scale;
            REFUSED(rmf_wire_sweep(poly, 3, tiny, NULL, 0, &o, &out), RMF_ERROR_INVALID_INPUT,
                    "options->scale_knots[1] (the scale of knot 0): the scale NaN");
            o.scale_knots = tame, o.method = RMF_SPINE_MOBIUS;
            REFUSED(rmf_wire_sweep(poly, 3, tiny, NULL, 0, &o, &out), RMF_ERROR_INVALID_INPUT,
                    "options->scale_knots = [(0.5, 2)] with options->method = 2: a scale law is exact");
        }
        rmf_curve_free(tiny);
    }
    /* Accessors on NULL and out of range; no file for a failure. */
    CHECK(rmf_shape_face_count(NULL) == 0 && rmf_shape_is_solid(NULL) == 0, "NULL has no faces");
    {
        RmfShape *shape = NULL;
        RmfShapeFace face;
        RmfSweepReport r;
        const RmfCurve *c = NULL;
        CHECK_STATUS(rmf_wire_sweep(e, 3, profile, NULL, 0, NULL, &shape), RMF_OK, "");
        CHECK_STATUS(rmf_shape_face(shape, 99, &face), RMF_ERROR_INVALID_INPUT, "index = 99");
        CHECK_STATUS(rmf_shape_face(NULL, 0, &face), RMF_ERROR_NULL_POINTER, "shape");
        CHECK_STATUS(rmf_shape_face_loop(shape, 0, 0, &c), RMF_ERROR_INVALID_INPUT, "loop = 0");
        CHECK(c == NULL, "no loop written");
        CHECK_STATUS(rmf_shape_report(shape, NULL), RMF_ERROR_NULL_POINTER, "out");
        CHECK_STATUS(rmf_shape_report(NULL, &r), RMF_ERROR_NULL_POINTER, "shape");
        CHECK_STATUS(rmf_shape_write_step(shape, NULL), RMF_ERROR_NULL_POINTER, "path");
        CHECK_STATUS(rmf_shape_write_step(shape, "no/such/directory/pipe.step"), RMF_ERROR_IO,
                     "cannot write");
        CHECK(fopen("no/such/directory/pipe.step", "r") == NULL, "nothing written");
        rmf_shape_free(shape);
        rmf_shape_free(NULL);
    }
    rmf_curve_free(open);
    rmf_curve_free(sq);
    rmf_curve_free(small);
    rmf_curve_free(profile);
}

/* Sweeps between two profiles (rmf_wire_sweep_between; intended behaviour of the geometry):
   two concentric circles, radius 1 at the start and 0.5 at the end of a line of length 3,
   are the frustum of volume pi L (r0^2 + r0 r1 + r1^2) / 3; a square (half side 0.5) into a
   circle (radius 0.6) along a line of 4 is a closed solid whose volume lies between the
   square's prism and the circle's (its quarters start on the x axis: the circle is cut where
   the square's corners point, on its diagonals, and the section does not turn). Then the bad
   inputs: a NULL end profile, a different number of holes and a closed wire, each refused
   with *out untouched. */
static void test_sweep_between(void) {
    RmfEdge e = line(vec3(0, 0, 0), vec3(3, 0, 0)), e4 = line(vec3(0, 0, 0), vec3(4, 0, 0));
    RmfCurve *big = circle(1), *small = circle(0.5), *sq = square(0.5), *round = NULL, *hole = circle(0.2);
    RmfShape *shape = NULL;
    CHECK_STATUS(rmf_curve_circle(vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0), 0.6, &round), RMF_OK, "");
    const double r0 = 1, r1 = 0.5, length = 3, exact = PI * length * (r0 * r0 + r0 * r1 + r1 * r1) / 3;
    CHECK_STATUS(rmf_wire_sweep_between(&e, 1, big, NULL, 0, small, NULL, 0, NULL, &shape), RMF_OK, "");
    if (shape) {
        const double v = volume(shape);
        printf("circle 1 into circle 0.5 along a line of 3: volume %.15f vs the frustum %.15f (relative %.1e)\n", v,
               exact, fabs(v - exact) / exact);
        CHECK(rmf_shape_is_solid(shape) == 1, "a closed solid");
        CHECK(fabs(v - exact) <= 1e-12 * exact, "the frustum's volume pi L (r0^2 + r0 r1 + r1^2) / 3");
    }
    rmf_shape_free(shape);
    shape = NULL;
    CHECK_STATUS(rmf_wire_sweep_between(&e4, 1, sq, NULL, 0, round, NULL, 0, NULL, &shape), RMF_OK, "");
    if (shape) {
        const double v = volume(shape), square_prism = 4 * 1.0, circle_prism = 4 * PI * 0.36;
        printf("square 0.5 into circle 0.6 along a line of 4: %zu faces, volume %.15f between %.6f and %.6f\n",
               rmf_shape_face_count(shape), v, square_prism, circle_prism);
        CHECK(rmf_shape_is_solid(shape) == 1, "a closed solid");
        CHECK(v > square_prism && v < circle_prism, "between the square's prism and the circle's");
    }
    rmf_shape_free(shape);
    {
        const RmfCurve *holes[1] = {hole};
        const RmfEdge loop[4] = {line(vec3(0, 0, 0), vec3(10, 0, 0)), line(vec3(10, 0, 0), vec3(10, 10, 0)),
                                 line(vec3(10, 10, 0), vec3(0, 10, 0)), line(vec3(0, 10, 0), vec3(0, 0, 0))};
        REFUSED(rmf_wire_sweep_between(&e, 1, big, NULL, 0, NULL, NULL, 0, NULL, &out), RMF_ERROR_NULL_POINTER,
                "end_profile");
        REFUSED(rmf_wire_sweep_between(&e, 1, big, holes, 1, small, NULL, 0, NULL, &out), RMF_ERROR_INVALID_INPUT,
                "end_profile: it has 0 holes, the profile 1");
        REFUSED(rmf_wire_sweep_between(&e, 1, big, NULL, 0, small, NULL, 1, NULL, &out), RMF_ERROR_NULL_POINTER,
                "end_holes");
        REFUSED(rmf_wire_sweep_between(loop, 4, big, NULL, 0, small, NULL, 0, NULL, &out), RMF_ERROR_INVALID_INPUT,
                "end_profile: a closed wire");
        CHECK_STATUS(rmf_wire_sweep_between(&e, 1, big, NULL, 0, small, NULL, 0, NULL, NULL), RMF_ERROR_NULL_POINTER,
                     "out");
    }
    rmf_curve_free(hole);
    rmf_curve_free(round);
    rmf_curve_free(sq);
    rmf_curve_free(small);
    rmf_curve_free(big);
}

/* Sweeps through sections (rmf_wire_sweep_through; intended behaviour of the geometry):
   circles of radii 0.5 at 0, 1 at 0.25 and 0.3 at 1 along a line of 4 are the chain of two
   frustums, volume pi/3 sum L_i (a_i^2 + a_i a_i+1 + a_i+1^2), by this suite's own
   integration (the check can fail: the same circles swept from the first straight into the
   last, without the middle one, differ). Then the bad inputs, each refused with *out
   untouched and the message naming the field: one section, the fractions out of order, a
   NULL profile in a section, a hole count that differs, NULL sections. */
static void test_sweep_through(void) {
    const double length = 4, at[3] = {0, 0.25, 1}, radius[3] = {0.5, 1.0, 0.3};
    RmfEdge e = line(vec3(0, 0, 0), vec3(length, 0, 0));
    RmfCurve *circles[3] = {circle(radius[0]), circle(radius[1]), circle(radius[2])}, *hole = circle(0.1);
    const RmfCurve *holes[1] = {hole};
    RmfWireSection sections[3];
    RmfShape *shape = NULL;
    double exact = 0;
    for (int k = 0; k < 3; ++k) {
        sections[k].at = at[k], sections[k].profile = circles[k];
        sections[k].holes = NULL, sections[k].hole_count = 0;
        if (k < 2) {
            const double a = radius[k], b = radius[k + 1];
            exact += PI / 3 * (at[k + 1] - at[k]) * length * (a * a + a * b + b * b);
        }
    }
    CHECK_STATUS(rmf_wire_sweep_through(&e, 1, sections, 3, NULL, &shape), RMF_OK, "");
    if (shape) {
        const double v = volume(shape);
        printf("circles 0.5 at 0, 1 at 0.25, 0.3 at 1 along a line of 4: %zu faces, volume %.15f vs the frustums "
               "%.15f (relative %.1e)\n",
               rmf_shape_face_count(shape), v, exact, fabs(v - exact) / exact);
        CHECK(rmf_shape_is_solid(shape) == 1, "a closed solid");
        CHECK(fabs(v - exact) <= 1e-12 * exact, "the chain of frustums pi/3 sum L_i (a_i^2 + a_i a_i+1 + a_i+1^2)");
    }
    rmf_shape_free(shape);
    shape = NULL;
    {
        const RmfWireSection ends[2] = {sections[0], {1, circles[2], NULL, 0}};
        CHECK_STATUS(rmf_wire_sweep_through(&e, 1, ends, 2, NULL, &shape), RMF_OK, "");
        if (shape) CHECK(fabs(volume(shape) - exact) > 0.1 * exact, "the middle section changes the volume");
        rmf_shape_free(shape);
    }
    {
        RmfWireSection bad[3] = {sections[0], sections[1], sections[2]};
        REFUSED(rmf_wire_sweep_through(&e, 1, sections, 1, NULL, &out), RMF_ERROR_INVALID_INPUT, "section_count = 1");
        bad[1].at = 1.5;
        REFUSED(rmf_wire_sweep_through(&e, 1, bad, 3, NULL, &out), RMF_ERROR_INVALID_INPUT, "sections[1].at = 1.5");
        bad[1] = sections[1], bad[1].profile = NULL;
        REFUSED(rmf_wire_sweep_through(&e, 1, bad, 3, NULL, &out), RMF_ERROR_NULL_POINTER, "sections[1].profile");
        bad[1] = sections[1], bad[1].holes = holes, bad[1].hole_count = 1;
        REFUSED(rmf_wire_sweep_through(&e, 1, bad, 3, NULL, &out), RMF_ERROR_INVALID_INPUT,
                "sections[1].holes: it has 1 holes, the profile 0");
        REFUSED(rmf_wire_sweep_through(&e, 1, NULL, 3, NULL, &out), RMF_ERROR_NULL_POINTER, "sections");
        CHECK_STATUS(rmf_wire_sweep_through(&e, 1, sections, 3, NULL, NULL), RMF_ERROR_NULL_POINTER, "out");
    }
    rmf_curve_free(hole);
    for (int k = 0; k < 3; ++k) rmf_curve_free(circles[k]);
}

int main(void) {
    gauss_init();
    test_options();
    test_pipe_route();
    test_corners();
    test_closed_nurbs();
    test_bad_inputs();
    test_options_of_an_older_header();
    test_scale_law_frustum();
    test_scale_knots_frustums();
    test_spine_methods();
    test_pipe_frame();
    test_sweep_between();
    test_sweep_through();
    test_guide_frame();
    return rmf_check_exit_code("abi_wire");
}
