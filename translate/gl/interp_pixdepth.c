/* interp_pixdepth.c: the depth of bitmaps and pixel rectangles (GL 2.1
 * 3.6.5, 3.7: their fragments take the raster position's window z and go
 * through the depth test like any other).
 *
 * The overlay of interp_pixels.c is one image for the frame. Where every
 * pixel draw of the frame (since its last clear) was depth-tested
 * (GL_LESS or GL_LEQUAL, depth writes on) at one raster depth given by
 * glRasterPos under the camera's own projection and viewport, the
 * overlay lies in that plane of constant window z in eye space: geometry
 * nearer hides it, whether drawn before (GL's test of the pixels) or after
 * (GL's test against the depth the pixels wrote), and geometry behind it
 * is hidden (a raster position set before the frame's first draw is the
 * camera's when that draw's projection and viewport are its). Pixels
 * drawn without a depth test stay in front of the whole scene, exact when
 * nothing drawn after the overlay's first pixels reaches their box in the
 * image (interp_dest_after_overlay); any other mix is noted.
 */
#include "interp_internal.h"

#include <string.h>

enum { DEPTH_NONE, DEPTH_PLANE, DEPTH_FRONT, DEPTH_MIXED };

void interp_pixdepth_raster(interp *ip, const double clip[4])
{
    gl_attribs *a = &ip->st.a;
    a->current.raster_in_camera = false;
    if (ip->frame_begin || !(clip[3] > 0))
        return;
    const mat4 *proj = interp_matrix(ip, INTERP_PROJ);
    if (!ip->camera_fixed) {
        /* Bitmap text before the first draw: in the camera if the camera
         * the frame's draws fix has this projection and viewport. */
        if (!ip->raster_pre) {
            ip->raster_pre = true;
            ip->raster_pre_proj = *proj;
            memcpy(ip->raster_pre_vp, a->viewport.rect, sizeof ip->raster_pre_vp);
        } else if (!mat4_equal_f32(proj, &ip->raster_pre_proj) ||
                   memcmp(a->viewport.rect, ip->raster_pre_vp, sizeof ip->raster_pre_vp) != 0) {
            ip->raster_pre_mixed = true;
        }
        a->current.raster_ndc_z = clip[2] / clip[3];
        a->current.raster_in_camera = true;
        return;
    }
    if (!mat4_equal_f32(proj, &ip->own_proj) ||
        memcmp(a->viewport.rect, ip->own_vp, sizeof ip->own_vp) != 0)
        return;
    a->current.raster_ndc_z = clip[2] / clip[3];
    a->current.raster_in_camera = true;
}

void interp_pixdepth_draw(interp *ip)
{
    const gl_attribs *a = &ip->st.a;
    if (ip->scene && !ip->scene->overlay)
        ip->pixels_depth_state = DEPTH_NONE; /* the frame's, or a clear's, first pixels */
    int kind;
    if (!a->caps[INTERP_CAP_DEPTH_TEST])
        kind = DEPTH_FRONT;
    else if ((a->depth.func == GL_LESS || a->depth.func == GL_LEQUAL) && a->depth.mask &&
             a->current.raster_in_camera)
        kind = DEPTH_PLANE;
    else
        kind = DEPTH_MIXED;
    if (ip->pixels_depth_state == DEPTH_NONE) {
        ip->pixels_depth_state = kind;
        ip->pixels_ndc_z = a->current.raster_ndc_z;
    } else if (ip->pixels_depth_state != kind ||
               (kind == DEPTH_PLANE && ip->pixels_ndc_z != a->current.raster_ndc_z)) {
        ip->pixels_depth_state = DEPTH_MIXED;
    }
}

bool interp_pixdepth_end_frame(interp *ip, bool drawn_after)
{
    scene *s = ip->scene;
    if (ip->pixels_depth_state == DEPTH_FRONT)
        return !drawn_after; /* GL draws later geometry over them */
    if (ip->pixels_depth_state != DEPTH_PLANE)
        return false;
    if (ip->raster_pre &&
        (ip->raster_pre_mixed || !ip->camera_fixed ||
         !mat4_equal_f32(&ip->raster_pre_proj, &ip->own_proj) ||
         memcmp(ip->raster_pre_vp, ip->own_vp, sizeof ip->own_vp) != 0))
        return false; /* some raster position was not the camera's */
    /* Window z is constant where ndc z = (row 2 . e) / (row 3 . e) is:
     * the plane (row 2 - z row 3) . e = 0 of eye space, the scene's. */
    const double *m = ip->cam_proj.m;
    double z = ip->pixels_ndc_z;
    for (int k = 0; k < 4; k++)
        s->overlay_plane[k] = m[k * 4 + 2] - z * m[k * 4 + 3];
    s->overlay_at_depth = true;
    return true;
}
