/* interp_pstipple.c: polygon stipple (GL 2.1 3.5.2), kept to window pixels.
 *
 * GL draws a polygon's fragment at window (x, y) only when bit (x mod 32,
 * y mod 32) of the mask is set, the mask's rows counted from the window's
 * bottom. The mask is state (GL_POLYGON_STIPPLE_BIT); a filled draw made
 * with GL_POLYGON_STIPPLE on carries it in its look, with the window
 * position of the camera's image, and the writer cuts the surface to the
 * set pixels in screen space (povwrite_pstipple.c). Lines and points (also
 * polygons drawn in GL_LINE or GL_POINT mode) are not stippled by it.
 */
#include "interp_internal.h"

#include <string.h>

void interp_polygonstipple(interp *ip, const rgl_cmd *cmd)
{
    if (interp_reject_in_begin(ip))
        return;
    uint32_t id = (uint32_t)cmd->arg[0].v.u, lost = 0;
    if (!id)
        return; /* unread (a NULL mask is GL's error too): the mask stays */
    interp_unrec_pixel_uses(ip, false, false, true);
    const uint8_t *bits = ip->scene ? interp_pixels_fetch(ip, id, 128, &lost) : NULL;
    if (bits)
        memcpy(ip->st.a.polygon.stipple, bits, 128);
}

void interp_pstipple_look(const interp *ip, scene_look *look)
{
    const gl_attribs *a = &ip->st.a;
    if (!a->caps[INTERP_CAP_POLYGON_STIPPLE])
        return;
    bool all = true;
    for (int i = 0; i < 128 && all; i++)
        all = a->polygon.stipple[i] == 0xff;
    if (all)
        return;
    if (!ip->scene)
        return;
    look->pstipple = scene_pstipple_index(ip->scene, a->polygon.stipple);
    if (!look->pstipple)
        return; /* out of memory: the scene is failed */
    for (int k = 0; k < 2; k++) {
        int64_t o = (int64_t)ip->cam_viewport[k] % 32;
        look->pstipple_org[k] = (uint8_t)(o < 0 ? o + 32 : o);
    }
}
