/* interp_stipple.c: line stipple (GL 1.x 3.4.2), cut in window space.
 *
 * GL counts the fragments of a line along its major axis with a counter s
 * that restarts at glBegin and before every segment of GL_LINES (it runs
 * on along a strip or a loop), and draws fragment s when bit
 * (s / factor) mod 16 of the pattern is set. The translator knows the
 * window mapping: a segment of n fragments (one per pixel of its extent
 * along the major axis) is cut into the runs of set bits, each the stretch
 * of the segment over fragments i0 to i1, counted from where it enters the
 * window (GL clips before it rasterises); those stretches are taken back
 * into eye space through the perspective divide, so each dash covers GL's
 * fragments.
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

static bool bit_on(const interp *ip, uint64_t s)
{
    const gl_attribs *a = &ip->st.a;
    return (a->line.stipple_pattern >> ((s / (uint64_t)a->line.stipple_factor) % 16)) & 1;
}

/* The eye-space fraction of segment p0-p1 at window fraction t. */
static double eye_fraction(const scene_camera *cam, const double p0[3], const double p1[3],
                           double t)
{
    if (cam->kind == SCENE_CAMERA_ORTHOGRAPHIC)
        return t;
    double dl = sqrt(cam->direction[0] * cam->direction[0] + cam->direction[1] * cam->direction[1] +
                     cam->direction[2] * cam->direction[2]);
    double d0 = 0, d1 = 0;
    for (int k = 0; k < 3; k++) {
        d0 += (p0[k] - cam->location[k]) * cam->direction[k] / dl;
        d1 += (p1[k] - cam->location[k]) * cam->direction[k] / dl;
    }
    double den = (1 - t) * d1 + t * d0;
    if (!(d0 > 0) || !(d1 > 0) || !(den > 0))
        return t;
    return t * d0 / den;
}

/* The part [*ta, *tb] of window segment w0-w1 inside the window (centred
 * coordinates, scene_camera_project's); false when none. */
static bool window_part(const scene_camera *cam, const double w0[2], const double w1[2],
                        double *ta, double *tb)
{
    double lim[2] = {cam->width * 0.5, cam->height * 0.5};
    *ta = 0;
    *tb = 1;
    for (int a = 0; a < 2; a++) {
        double d = w1[a] - w0[a];
        for (int sgn = -1; sgn <= 1; sgn += 2) {
            /* keep sgn * (w0 + t d) <= lim */
            double num = lim[a] - sgn * w0[a], den = sgn * d;
            if (den == 0) {
                if (num < 0)
                    return false;
                continue;
            }
            double t = num / den;
            if (den > 0)
                *tb = fmin(*tb, t);
            else
                *ta = fmax(*ta, t);
        }
    }
    return *ta < *tb;
}

size_t interp_stipple_dashes(const interp *ip, const scene_camera *cam, const double p0[3],
                             const double p1[3], const double w0[2], const double w1[2],
                             uint64_t *counter, double (*dash)[2], size_t max)
{
    /* GL clips the line first: the counter runs from the first fragment
     * inside the window. */
    double ta, tb;
    if (cam->width <= 0 || cam->height <= 0 || !window_part(cam, w0, w1, &ta, &tb))
        return 0;
    /* Along the major axis (mirrored when the segment runs backwards):
     * fragment i lies i pixels from the clipped start, and a segment
     * counts ceil(length) of them, as Mesa steps its lines (measured: the
     * dashes then fall on GL's pixels along strips, where rounding to
     * pixel centres drifts by a pixel per segment). */
    int ax = fabs(w1[0] - w0[0]) >= fabs(w1[1] - w0[1]) ? 0 : 1;
    double size = ax == 0 ? cam->width : cam->height;
    double a0 = w0[ax] + (w1[ax] - w0[ax]) * ta + size * 0.5;
    double a1 = w0[ax] + (w1[ax] - w0[ax]) * tb + size * 0.5;
    if (a1 < a0) {
        a0 = size - a0;
        a1 = size - a1;
    }
    if (!(a1 - a0 > 0) || !(a1 - a0 < 1e7))
        return 0;
    double m_first = a0, m_end = a0 + ceil(a1 - a0);
    uint64_t n = (uint64_t)(m_end - m_first);
    size_t k = 0;
    uint64_t s0 = *counter;
    for (uint64_t i = 0; i < n && k < max;) {
        if (!bit_on(ip, s0 + i)) {
            i++;
            continue;
        }
        uint64_t j = i;
        while (j < n && bit_on(ip, s0 + j))
            j++;
        /* fragments i..j-1 cover [m_first + i, m_first + j] */
        double xa = fmax(m_first + (double)i, a0), xb = fmin(m_first + (double)j, a1);
        double fa = ta + (tb - ta) * (xa - a0) / (a1 - a0);
        double fb = ta + (tb - ta) * (xb - a0) / (a1 - a0);
        dash[k][0] = eye_fraction(cam, p0, p1, fa);
        dash[k][1] = eye_fraction(cam, p0, p1, fb);
        k++;
        i = j;
    }
    *counter += n;
    return k;
}
