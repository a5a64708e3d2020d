/* accum_dof.c: depth of field through the accumulation buffer: 8 passes,
 * the eye moved around the view axis, focused on the middle quad (z = -5). */
#include "accum.h"

static void accum_pass(int i, int w, int h)
{
    double x, y;
    accum_sample(i, &x, &y);
    accum_camera(w, h, 0, 0, 0.12 * x, 0.12 * y, 5.0);
}
