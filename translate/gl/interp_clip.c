/* interp_clip.c: user clip planes (GL 1.x 2.12): glClipPlane and the
 * GL_CLIP_PLANEi enables.
 *
 * glClipPlane's plane is transformed into eye space by the inverse of the
 * modelview current at the call, and kept there (p' = p M^-1): later
 * changes of the modelview do not move it. A primitive keeps the points
 * whose eye coordinates satisfy p' . (x, y, z, w) >= 0 for every enabled
 * plane. Triangles and solids carry the enabled planes in their look and
 * the writer clips them exactly (clipped_by planes in eye space); lines are
 * clipped here, as GL clips them (the colour interpolated to the cut), and
 * a point is kept or dropped by its centre, as GL does.
 */
#include "interp_internal.h"

#include <math.h>

/* Mesa's GL_MAX_CLIP_PLANES, as many as the caps table holds. */
#define CLIP_PLANES 8

void interp_clipplane(interp *ip, const rgl_cmd *cmd)
{
    GLenum plane = arg_enum(cmd, 0);
    if (plane < GL_CLIP_PLANE0 || plane >= GL_CLIP_PLANE0 + CLIP_PLANES) {
        interp_bad_enum(ip, "clip plane", plane);
        return;
    }
    const rgl_arg *eq = &cmd->arg[1];
    double p[4];
    for (int k = 0; k < 4; k++)
        p[k] = k < (int)eq->count ? eq->array[k] : 0;
    for (int k = 0; k < 4; k++)
        if (!isfinite(p[k])) {
            interp_diag(ip, DIAG_BAD_NUMBER, "glClipPlane with a NaN or infinite coefficient: "
                        "ignored");
            return;
        }
    mat4 inv;
    double *out = ip->st.a.transform.clip_plane[plane - GL_CLIP_PLANE0];
    if (!mat4_invert(interp_matrix(ip, INTERP_MV), &inv)) {
        /* GL leaves this undefined; the plane is kept as given. */
        for (int k = 0; k < 4; k++)
            out[k] = p[k];
        return;
    }
    for (int j = 0; j < 4; j++) /* row vector times M^-1: column j of it */
        out[j] = p[0] * inv.m[j * 4 + 0] + p[1] * inv.m[j * 4 + 1] + p[2] * inv.m[j * 4 + 2] +
                 p[3] * inv.m[j * 4 + 3];
}

/* The enabled planes, normalised (a plane of zero normal keeps all or
 * nothing by the sign of d, as GL's test does). Returns how many. */
static int enabled_planes(const interp *ip, double out[CLIP_PLANES][4])
{
    const gl_attribs *a = &ip->st.a;
    int n = 0;
    for (int i = 0; i < CLIP_PLANES; i++) {
        if (!a->caps[INTERP_CAP_CLIP_PLANE0 + i])
            continue;
        const double *p = a->transform.clip_plane[i];
        double l = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        for (int k = 0; k < 4; k++)
            out[n][k] = l > 0 ? p[k] / l : p[k];
        n++;
    }
    return n;
}

uint32_t interp_clip_look(interp *ip)
{
    double planes[CLIP_PLANES][4];
    int n = enabled_planes(ip, planes);
    if (n == 0 || !ip->scene)
        return 0;
    return scene_clip_index(ip->scene, (const double(*)[4])planes, (uint32_t)n);
}

static double side(const double p[4], const double x[3])
{
    return p[0] * x[0] + p[1] * x[1] + p[2] * x[2] + p[3];
}

bool interp_clip_segment(const interp *ip, double p0[3], double p1[3], double *t0, double *t1)
{
    double planes[CLIP_PLANES][4], a[3], b[3];
    int n = enabled_planes(ip, planes);
    *t0 = 0;
    *t1 = 1;
    if (n == 0)
        return true;
    for (int k = 0; k < 3; k++) {
        a[k] = p0[k];
        b[k] = p1[k];
    }
    for (int i = 0; i < n; i++) {
        double da = side(planes[i], a), db = side(planes[i], b);
        if (da < 0 && db < 0)
            return false;
        if (da >= 0 && db >= 0)
            continue;
        double t = da / (da - db); /* along the original segment: */
        double at = *t0 + (*t1 - *t0) * t;
        if (da < 0)
            *t0 = at;
        else
            *t1 = at;
        for (int k = 0; k < 3; k++) {
            double x = p0[k] + (p1[k] - p0[k]) * at;
            if (da < 0)
                a[k] = x;
            else
                b[k] = x;
        }
    }
    for (int k = 0; k < 3; k++) {
        p0[k] = a[k];
        p1[k] = b[k];
    }
    return true;
}

bool interp_clip_point(const interp *ip, const double p[3])
{
    double planes[CLIP_PLANES][4];
    int n = enabled_planes(ip, planes);
    for (int i = 0; i < n; i++)
        if (side(planes[i], p) < 0)
            return false;
    return true;
}
