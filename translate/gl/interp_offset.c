/* interp_offset.c: glPolygonOffset (GL 1.x 3.5.5).
 *
 * GL moves the window depth of a polygon's fragments by
 * factor * (depth slope) + units * (smallest depth step) when the offset of
 * its polygon mode is enabled (GL_POLYGON_OFFSET_FILL, _LINE, _POINT). Its
 * use is to let lines drawn over a surface of the same shape win the depth
 * test (hidden-line wireframes, decals). A ray tracer has no depth buffer:
 * an offset polygon is moved along the camera's rays by one pixel's width
 * at its distance (away from the eye for a positive offset, toward it for
 * a negative one), which keeps its image and puts the lines GL draws over
 * it (thin solids half a pixel wide, docs/mapping.md section 7) wholly in
 * front. An offset shape is drawn as GL's facets, not as a true solid:
 * the lines of its wireframe lie on those facets and a true sphere would
 * bulge over them. The move is not GL's depth offset: a note says so.
 */
#include "interp_internal.h"

#include <math.h>

/* The offset that applies to polygons drawn now: 0 none, 1 away from the
 * eye, -1 toward it. The front face's polygon mode picks the enable. */
static int offset_sign(const interp *ip)
{
    const gl_attribs *a = &ip->st.a;
    int cap;
    switch (a->polygon.mode[0]) {
    case GL_LINE: cap = INTERP_CAP_POLYGON_OFFSET_LINE; break;
    case GL_POINT: cap = INTERP_CAP_POLYGON_OFFSET_POINT; break;
    default: cap = INTERP_CAP_POLYGON_OFFSET_FILL; break;
    }
    if (!a->caps[cap])
        return 0;
    /* Usual offsets have factor and units of one sign; their sum says
     * which way GL moves a polygon at a moderate slope. */
    double d = (double)a->polygon.offset_factor + (double)a->polygon.offset_units;
    return d > 0 ? 1 : d < 0 ? -1 : 0;
}

bool interp_offset_active(const interp *ip) { return offset_sign(ip) != 0; }

void interp_offset_apply(interp *ip, mat4 *to_eye)
{
    if (ip->prim_mode <= GL_LINE_STRIP || !ip->scene)
        return; /* points and lines: GL offsets polygons only */
    int sign = offset_sign(ip);
    if (!sign)
        return;
    const scene_camera *cam = &ip->scene->camera;
    double ul = sqrt(cam->up[0] * cam->up[0] + cam->up[1] * cam->up[1] + cam->up[2] * cam->up[2]);
    double dl = sqrt(cam->direction[0] * cam->direction[0] +
                     cam->direction[1] * cam->direction[1] +
                     cam->direction[2] * cam->direction[2]);
    int h = cam->height > 0 ? cam->height : 1;
    if (!(ul > 0) || !(dl > 0) || !isfinite(ul) || !isfinite(dl))
        return;
    interp_note(ip, DIAG_NOTE_POLYGON_OFFSET);
    mat4 s = mat4_identity();
    if (cam->kind == SCENE_CAMERA_ORTHOGRAPHIC) {
        double px = ul / h; /* one pixel, in eye units */
        for (int i = 0; i < 3; i++)
            s.m[12 + i] = sign * cam->direction[i] / dl * px;
    } else {
        /* Scaled about the eye: every point moves along its own ray by one
         * pixel's width at its distance. */
        double f = 1 + sign * (ul / dl) / h;
        for (int i = 0; i < 3; i++) {
            s.m[i * 5] = f;
            s.m[12 + i] = cam->location[i] * (1 - f);
        }
    }
    *to_eye = mat4_mul(&s, to_eye);
}
