/*
 * A program that uses an installed rmfsurf, as a C or C++ project outside this repository
 * would: built by examples/consumers/make (pkg-config) and examples/consumers/cmake
 * (find_package), and run by the test command (integration/tests/install.rs).
 *
 * It checks that the library it loaded is the one its header describes, sweeps a circle of
 * radius 0.25 along a PH cubic spline through a helix with the rational rotation-minimizing
 * frame, and checks the surface with its own arithmetic: every point of the sweep is 0.25
 * from the spine point of the same parameter, in the plane normal to the spine there.
 * It prints "consumer OK" and exits 0 when everything holds.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <rmfsurf.h>

#define RADIUS 0.25

static int failed(const char *what, RmfStatus status) {
    fprintf(stderr, "consumer: %s: %s: %s\n", what, rmf_status_name(status), rmf_last_error());
    return 1;
}

static double dot(RmfVec3 a, RmfVec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static RmfVec3 sub(RmfVec3 a, RmfVec3 b) {
    RmfVec3 d;
    d.x = a.x - b.x;
    d.y = a.y - b.y;
    d.z = a.z - b.z;
    return d;
}

/* The unit circle of radius RADIUS as a rational quadratic NURBS (nine poles). */
static RmfStatus circle(RmfCurve **out) {
    const double s = sqrt(0.5);
    const double x[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, y[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
    const double w[9] = {1, s, 1, s, 1, s, 1, s, 1};
    const double knots[12] = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
    RmfVec3 poles[9];
    int i;
    for (i = 0; i < 9; i++) {
        poles[i].x = RADIUS * x[i];
        poles[i].y = RADIUS * y[i];
        poles[i].z = 0;
    }
    return rmf_nurbs_curve_create(2, poles, w, 9, knots, 12, out);
}

int main(void) {
    char expected[64];
    RmfVec3 points[9], tangents[9], normal = {0, 0, 1};
    RmfCurve *spine = NULL, *profile = NULL;
    RmfFrames *frames = NULL;
    RmfSurface *surface = NULL;
    double u0, u1, v0, v1, worst = 0;
    RmfStatus status;
    int i, j, code = 1;

    snprintf(expected, sizeof expected, "%d.%d.%d", RMF_VERSION_MAJOR, RMF_VERSION_MINOR,
             RMF_VERSION_PATCH);
    if (strcmp(rmf_version(), expected) != 0) {
        fprintf(stderr, "consumer: header %s, library %s\n", expected, rmf_version());
        return 1;
    }
    /* A refused call: a status, its name and a message naming the argument. */
    status = rmf_curve_domain(NULL, &u0, &u1);
    if (status != RMF_ERROR_NULL_POINTER || strlen(rmf_last_error()) == 0) {
        fprintf(stderr, "consumer: a NULL curve gave %s\n", rmf_status_name(status));
        return 1;
    }

    for (i = 0; i < 9; i++) {
        double a = 0.5 * i;
        points[i].x = cos(a);
        points[i].y = sin(a);
        points[i].z = 0.2 * a;
        tangents[i].x = -sin(a);
        tangents[i].y = cos(a);
        tangents[i].z = 0.2;
    }
    if ((status = rmf_ph_spline_hermite(points, tangents, 9, &spine)) != RMF_OK)
        return failed("rmf_ph_spline_hermite", status);
    if ((status = rmf_ph_rational_rmf(spine, normal, &frames)) != RMF_OK) {
        code = failed("rmf_ph_rational_rmf", status);
        goto done;
    }
    if ((status = circle(&profile)) != RMF_OK) {
        code = failed("rmf_nurbs_curve_create", status);
        goto done;
    }
    if ((status = rmf_sweep_surface(spine, frames, profile, &surface)) != RMF_OK) {
        code = failed("rmf_sweep_surface", status);
        goto done;
    }
    rmf_surface_domain(surface, &u0, &u1, &v0, &v1);
    for (i = 0; i <= 40; i++) {
        for (j = 0; j <= 40; j++) {
            double u = u0 + (u1 - u0) * i / 40, v = v0 + (v1 - v0) * j / 40;
            RmfVec3 s, x, dx, d;
            if ((status = rmf_surface_eval(surface, u, v, &s, NULL, NULL)) != RMF_OK ||
                (status = rmf_curve_eval(spine, v, &x, &dx)) != RMF_OK) {
                code = failed("evaluation", status);
                goto done;
            }
            d = sub(s, x);
            worst = fmax(worst, fabs(sqrt(dot(d, d)) - RADIUS));
            worst = fmax(worst, fabs(dot(d, dx)) / sqrt(dot(dx, dx)));
        }
    }
    printf("consumer: rmfsurf %s, sweep off its circle by %.2e (limit 1e-12)\n", rmf_version(),
           worst);
    code = worst <= 1e-12 ? 0 : 1;
    if (code == 0) printf("consumer OK\n");

done:
    rmf_surface_free(surface);
    rmf_curve_free(profile);
    rmf_frames_free(frames);
    rmf_curve_free(spine);
    return code;
}
