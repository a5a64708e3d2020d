/* interp_stipple.c: line stipple (GL 1.x 3.4.2), cut in window space as
 * Mesa cuts it.
 *
 * GL counts the fragments of a line along its major axis with a counter s
 * that restarts at glBegin and before every segment of GL_LINES (it runs
 * on along a strip or a loop), and draws fragment s when bit
 * (s / factor) mod 16 of the pattern is set. Mesa (its draw module) splits
 * a clipped segment of major-axis length L into the dashes its set bits
 * give: fragment i of ceil(L) covers the fractions i / L to (i + 1) / L,
 * the bit of (int)s + i decides, and s then grows by L itself, not by the
 * pixels drawn. Each dash is then rasterised as a line of its own
 * (interp_lines.c), its ends by the diamond-exit rule.
 */
#include "interp_internal.h"

#include <math.h>

void interp_linestipple(interp *ip, const rgl_cmd *cmd)
{
    int64_t f = rgl_arg_i(&cmd->arg[0], 0);
    ip->st.a.line.stipple_factor = (int32_t)(f < 1 ? 1 : f > 256 ? 256 : f);
    ip->st.a.line.stipple_pattern = (uint16_t)cmd->arg[1].v.u;
}

bool interp_stipple_on(const interp *ip)
{
    const gl_attribs *a = &ip->st.a;
    return a->caps[INTERP_CAP_LINE_STIPPLE] && a->line.stipple_pattern != 0xffff;
}

static bool bit_on(const interp *ip, int64_t s)
{
    const gl_attribs *a = &ip->st.a;
    return (a->line.stipple_pattern >> ((s / a->line.stipple_factor) & 15)) & 1;
}

size_t interp_stipple_dashes(const interp *ip, const double w0[2], const double w1[2],
                             double *counter, double (*dash)[2], size_t max)
{
    /* Mesa's float arithmetic: a length, its ceiling, fractions of it. */
    float len = fmaxf(fabsf((float)(w1[0] - w0[0])), fabsf((float)(w1[1] - w0[1])));
    if (!(len > 0) || !(len < 1e7f))
        return 0;
    int64_t n = (int64_t)ceilf(len), s0 = (int64_t)*counter;
    size_t k = 0;
    bool on = false;
    float start = 0;
    for (int64_t i = 0; i < n && k < max; i++) {
        bool b = bit_on(ip, s0 + i);
        if (b == on)
            continue;
        if (on) {
            dash[k][0] = start / len;
            dash[k][1] = (float)i / len;
            k++;
        } else {
            start = (float)i;
        }
        on = b;
    }
    if (on && start < len && k < max) {
        dash[k][0] = start / len;
        dash[k][1] = 1;
        k++;
    }
    *counter = (double)((float)*counter + ceilf(len));
    return k;
}
