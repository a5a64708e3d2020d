/* accum_aa.c: antialiasing through the accumulation buffer: 8 passes, the
 * projection jittered by a sub-pixel offset each time. */
#include "accum.h"

static void accum_pass(int i, int w, int h)
{
    double x, y;
    accum_sample(i, &x, &y);
    accum_camera(w, h, x, y, 0, 0, 5.0);
}
