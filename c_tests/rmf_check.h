/*
 * Minimal test macros shared by the C and C++ tests. A failed check prints its location and
 * the library's last error and counts a failure; main returns rmf_check_exit_code().
 */
#ifndef RMF_TEST_CHECK_H
#define RMF_TEST_CHECK_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rmfsurf.h"

static int rmf_check_failures = 0;

/* Values the suites feed to the library as bad input. */
static inline double nan_value(void) { return strtod("nan", NULL); }
static inline double inf_value(void) { return strtod("inf", NULL); }

static inline RmfVec3 vec3(double x, double y, double z) {
    RmfVec3 v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}

#define CHECK(cond, what)                                                                     \
    do {                                                                                      \
        if (!(cond)) {                                                                        \
            fprintf(stderr, "%s:%d: FAILED: %s (%s)\n", __FILE__, __LINE__, what, #cond);     \
            rmf_check_failures++;                                                             \
        }                                                                                     \
    } while (0)

/* A call must return `expected`; a failing status must come with a non-empty message that
 * contains `mention` (the argument it names; "" to skip that part). */
#define CHECK_STATUS(call, expected, mention)                                                 \
    do {                                                                                      \
        RmfStatus rmf_status_ = (call);                                                       \
        if (rmf_status_ != (RmfStatus)(expected)) {                                           \
            fprintf(stderr, "%s:%d: FAILED: %s returned %s, expected %s; last error: %s\n",   \
                    __FILE__, __LINE__, #call, rmf_status_name(rmf_status_),                  \
                    rmf_status_name(expected), rmf_last_error());                             \
            rmf_check_failures++;                                                             \
        } else if ((expected) != RMF_OK &&                                                    \
                   (rmf_last_error()[0] == '\0' || !strstr(rmf_last_error(), mention))) {      \
            fprintf(stderr, "%s:%d: FAILED: %s: message \"%s\" does not name \"%s\"\n",        \
                    __FILE__, __LINE__, #call, rmf_last_error(), mention);                    \
            rmf_check_failures++;                                                             \
        }                                                                                     \
    } while (0)

static int rmf_check_exit_code(const char *suite) {
    if (rmf_check_failures) {
        fprintf(stderr, "%s: %d check(s) failed\n", suite, rmf_check_failures);
        return 1;
    }
    printf("%s: all checks passed\n", suite);
    return 0;
}

#endif
