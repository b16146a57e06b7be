/* Independent NURBS evaluation for the tests; see nurbs_eval.h. */
#include "nurbs_eval.h"

#include <math.h>
#include <string.h>

RmfVec3 ne_add(RmfVec3 a, RmfVec3 b) {
    RmfVec3 r;
    r.x = a.x + b.x;
    r.y = a.y + b.y;
    r.z = a.z + b.z;
    return r;
}

RmfVec3 ne_scale(RmfVec3 a, double s) {
    RmfVec3 r;
    r.x = a.x * s;
    r.y = a.y * s;
    r.z = a.z * s;
    return r;
}

RmfVec3 ne_sub(RmfVec3 a, RmfVec3 b) {
    RmfVec3 r;
    r.x = a.x - b.x;
    r.y = a.y - b.y;
    r.z = a.z - b.z;
    return r;
}

RmfVec3 ne_cross(RmfVec3 a, RmfVec3 b) {
    RmfVec3 r;
    r.x = a.y * b.z - a.z * b.y;
    r.y = a.z * b.x - a.x * b.z;
    r.z = a.x * b.y - a.y * b.x;
    return r;
}

double ne_dot(RmfVec3 a, RmfVec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
double ne_norm(RmfVec3 a) { return sqrt(ne_dot(a, a)); }
double ne_dist(RmfVec3 a, RmfVec3 b) { return ne_norm(ne_sub(a, b)); }
RmfVec3 ne_unit(RmfVec3 a) { return ne_scale(a, 1.0 / ne_norm(a)); }

/* A2.1: the knot span index i with U[i] <= u < U[i+1] (n = pole count − 1). */
static size_t find_span(size_t n, size_t p, double u, const double *U) {
    size_t low = p, high = n + 1, mid;
    if (u >= U[n + 1]) return n;
    if (u <= U[p]) return p;
    mid = (low + high) / 2;
    while (u < U[mid] || u >= U[mid + 1]) {
        if (u < U[mid]) high = mid; else low = mid;
        mid = (low + high) / 2;
    }
    return mid;
}

/* A2.3: ders[k][j] = k-th derivative of N_{span-p+j, p} at u, k ≤ nd. */
static void basis_derivatives(size_t span, double u, size_t p, size_t nd, const double *U,
                              double ders[3][NE_MAX_DEGREE + 1]) {
    double ndu[NE_MAX_DEGREE + 1][NE_MAX_DEGREE + 1];
    double a[2][NE_MAX_DEGREE + 1];
    double left[NE_MAX_DEGREE + 1], right[NE_MAX_DEGREE + 1];
    size_t j, r, k;
    ndu[0][0] = 1.0;
    for (j = 1; j <= p; j++) {
        double saved = 0.0;
        left[j] = u - U[span + 1 - j];
        right[j] = U[span + j] - u;
        for (r = 0; r < j; r++) {
            double temp;
            ndu[j][r] = right[r + 1] + left[j - r];
            temp = ndu[r][j - 1] / ndu[j][r];
            ndu[r][j] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        ndu[j][j] = saved;
    }
    for (j = 0; j <= p; j++) ders[0][j] = ndu[j][p];
    for (k = 1; k <= nd; k++)
        for (j = 0; j <= p; j++) ders[k][j] = 0.0;
    for (r = 0; r <= p; r++) {
        int s1 = 0, s2 = 1;
        a[0][0] = 1.0;
        for (k = 1; k <= nd && k <= p; k++) {
            double d = 0.0;
            long rk = (long)r - (long)k, pk = (long)p - (long)k, jj, j1, j2;
            if ((long)r >= (long)k) {
                a[s2][0] = a[s1][0] / ndu[pk + 1][rk];
                d = a[s2][0] * ndu[rk][pk];
            }
            j1 = (rk >= -1) ? 1 : -rk;
            j2 = ((long)r - 1 <= pk) ? (long)k - 1 : (long)p - (long)r;
            for (jj = j1; jj <= j2; jj++) {
                a[s2][jj] = (a[s1][jj] - a[s1][jj - 1]) / ndu[pk + 1][rk + jj];
                d += a[s2][jj] * ndu[rk + jj][pk];
            }
            if ((long)r <= pk) {
                a[s2][k] = -a[s1][k - 1] / ndu[pk + 1][r];
                d += a[s2][k] * ndu[r][pk];
            }
            ders[k][r] = d;
            { int t = s1; s1 = s2; s2 = t; }
        }
    }
    {
        double factor = (double)p;
        for (k = 1; k <= nd; k++) {
            for (j = 0; j <= p; j++) ders[k][j] *= factor;
            factor *= (double)p - (double)k;
        }
    }
}

static const double BINOMIAL[3][3] = {{1, 0, 0}, {1, 1, 0}, {1, 2, 1}};

void ne_curve_derivatives(const RmfNurbsCurve *c, double t, RmfVec3 d[3]) {
    size_t p = c->degree, n = c->pole_count - 1, span = find_span(n, p, t, c->knots), j, k, i;
    double ders[3][NE_MAX_DEGREE + 1];
    double aw[3][4];
    basis_derivatives(span, t, p, 2, c->knots, ders);
    memset(aw, 0, sizeof aw);
    for (k = 0; k < 3; k++) {
        for (j = 0; j <= p; j++) {
            size_t idx = span - p + j;
            double w = c->weights[idx];
            aw[k][0] += ders[k][j] * w * c->poles[idx].x;
            aw[k][1] += ders[k][j] * w * c->poles[idx].y;
            aw[k][2] += ders[k][j] * w * c->poles[idx].z;
            aw[k][3] += ders[k][j] * w;
        }
    }
    /* A4.2: C^(k) = (A^(k) − Σ_{i=1..k} C(k,i) w^(i) C^(k−i)) / w. */
    for (k = 0; k < 3; k++) {
        double v[3];
        v[0] = aw[k][0];
        v[1] = aw[k][1];
        v[2] = aw[k][2];
        for (i = 1; i <= k; i++) {
            v[0] -= BINOMIAL[k][i] * aw[i][3] * d[k - i].x;
            v[1] -= BINOMIAL[k][i] * aw[i][3] * d[k - i].y;
            v[2] -= BINOMIAL[k][i] * aw[i][3] * d[k - i].z;
        }
        d[k].x = v[0] / aw[0][3];
        d[k].y = v[1] / aw[0][3];
        d[k].z = v[2] / aw[0][3];
    }
}

void ne_surface_derivatives(const RmfNurbsSurface *s, double u, double v, RmfVec3 d[3][3]) {
    size_t pu = s->degree_u, pv = s->degree_v;
    size_t su = find_span(s->pole_count_u - 1, pu, u, s->knots_u);
    size_t sv = find_span(s->pole_count_v - 1, pv, v, s->knots_v);
    double nu[3][NE_MAX_DEGREE + 1], nv[3][NE_MAX_DEGREE + 1];
    double aw[3][3][4];
    size_t k, l, r, c, i, j;
    basis_derivatives(su, u, pu, 2, s->knots_u, nu);
    basis_derivatives(sv, v, pv, 2, s->knots_v, nv);
    memset(aw, 0, sizeof aw);
    for (k = 0; k < 3; k++) {
        for (l = 0; l + k < 3; l++) {
            for (r = 0; r <= pu; r++) {
                for (c = 0; c <= pv; c++) {
                    size_t idx = (su - pu + r) * s->pole_count_v + (sv - pv + c);
                    double b = nu[k][r] * nv[l][c], w = s->weights[idx];
                    aw[k][l][0] += b * w * s->poles[idx].x;
                    aw[k][l][1] += b * w * s->poles[idx].y;
                    aw[k][l][2] += b * w * s->poles[idx].z;
                    aw[k][l][3] += b * w;
                }
            }
        }
    }
    /* A4.4: rational surface derivatives from the homogeneous ones. */
    for (k = 0; k < 3; k++) {
        for (l = 0; l + k < 3; l++) {
            double vv[3];
            vv[0] = aw[k][l][0];
            vv[1] = aw[k][l][1];
            vv[2] = aw[k][l][2];
            for (j = 1; j <= l; j++) {
                vv[0] -= BINOMIAL[l][j] * aw[0][j][3] * d[k][l - j].x;
                vv[1] -= BINOMIAL[l][j] * aw[0][j][3] * d[k][l - j].y;
                vv[2] -= BINOMIAL[l][j] * aw[0][j][3] * d[k][l - j].z;
            }
            for (i = 1; i <= k; i++) {
                double v2[3] = {0.0, 0.0, 0.0};
                vv[0] -= BINOMIAL[k][i] * aw[i][0][3] * d[k - i][l].x;
                vv[1] -= BINOMIAL[k][i] * aw[i][0][3] * d[k - i][l].y;
                vv[2] -= BINOMIAL[k][i] * aw[i][0][3] * d[k - i][l].z;
                for (j = 1; j <= l; j++) {
                    v2[0] += BINOMIAL[l][j] * aw[i][j][3] * d[k - i][l - j].x;
                    v2[1] += BINOMIAL[l][j] * aw[i][j][3] * d[k - i][l - j].y;
                    v2[2] += BINOMIAL[l][j] * aw[i][j][3] * d[k - i][l - j].z;
                }
                vv[0] -= BINOMIAL[k][i] * v2[0];
                vv[1] -= BINOMIAL[k][i] * v2[1];
                vv[2] -= BINOMIAL[k][i] * v2[2];
            }
            d[k][l].x = vv[0] / aw[0][0][3];
            d[k][l].y = vv[1] / aw[0][0][3];
            d[k][l].z = vv[2] / aw[0][0][3];
        }
    }
}

double ne_gaussian_curvature(RmfVec3 d[3][3]) {
    RmfVec3 normal = ne_cross(d[1][0], d[0][1]);
    double area2 = ne_dot(normal, normal), len = sqrt(area2);
    RmfVec3 n;
    double L, M, N;
    n.x = normal.x / len;
    n.y = normal.y / len;
    n.z = normal.z / len;
    L = ne_dot(d[2][0], n);
    M = ne_dot(d[1][1], n);
    N = ne_dot(d[0][2], n);
    return (L * N - M * M) / area2;
}

double ne_parameter_line_cosine(RmfVec3 d[3][3]) {
    return fabs(ne_dot(d[1][0], d[0][1])) / (ne_norm(d[1][0]) * ne_norm(d[0][1]));
}

RmfVec3 ne_bezier_point(const RmfBezierCurve *seg, double s) {
    double h[NE_MAX_DEGREE + 1][4];
    size_t n = seg->degree, i, level;
    RmfVec3 r;
    for (i = 0; i <= n; i++) {
        h[i][0] = seg->weights[i] * seg->poles[i].x;
        h[i][1] = seg->weights[i] * seg->poles[i].y;
        h[i][2] = seg->weights[i] * seg->poles[i].z;
        h[i][3] = seg->weights[i];
    }
    for (level = n; level > 0; level--)
        for (i = 0; i < level; i++) {
            int c;
            for (c = 0; c < 4; c++) h[i][c] = (1.0 - s) * h[i][c] + s * h[i + 1][c];
        }
    r.x = h[0][0] / h[0][3];
    r.y = h[0][1] / h[0][3];
    r.z = h[0][2] / h[0][3];
    return r;
}
