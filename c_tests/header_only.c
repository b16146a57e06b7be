/* The public header must compile on its own, as C99 and as C++, with
 * -Wall -Wextra -Wpedantic -Werror (see capi/tests/c_suite.rs). */
#include "rmfsurf.h"

int main(void) {
    RmfVec3 v = {1.0, 2.0, 3.0};
    RmfStatus s = RMF_OK;
    unsigned major = RMF_VERSION_MAJOR;
    return (int)s + (v.x == 1.0 ? 0 : 1) + (int)(major > 1000u);
}
