/* accum_motion.c: motion blur through the accumulation buffer: 8 passes,
 * the whole scene moved a little to the right each time. */
#include "accum.h"

static void accum_pass(int i, int w, int h)
{
    accum_camera(w, h, 0, 0, 0, 0, 5.0);
    glTranslatef(0.03f * (float)i, 0, 0);
}
