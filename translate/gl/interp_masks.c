/* interp_masks.c: the colour and depth write masks (GL 1.x 4.2.2), and
 * draws into a colour buffer the frame does not show (interp_buffers.c),
 * which change no pixel of it either.
 *
 * With every colour channel masked (glColorMask all GL_FALSE), a draw
 * changes no pixel's colour: programs do it for passes that write only the
 * depth or stencil buffer. Such a draw is left out of the scene. When it
 * writes depth (depth test on, glDepthMask GL_TRUE), GL's later draws
 * behind it are hidden where it lies, which the scene does not do: a note
 * says so. A draw with some channels masked is drawn whole (noted).
 * A colour clear with some channels masked recolours what the frame holds
 * where that is flat colours (interp_masks_clear), else clears whole
 * (noted).
 */
#include "interp_internal.h"

bool interp_masks_hide(interp *ip)
{
    const gl_attribs *a = &ip->st.a;
    if (interp_draw_buffer_hidden(ip)) { /* into a buffer not shown: as if masked */
        if (ip->stencil.write) {
            ip->stencil.only = true;
            return false;
        }
        if (a->caps[INTERP_CAP_DEPTH_TEST] && a->depth.mask)
            interp_note(ip, DIAG_NOTE_DRAW_BUFFER_DEPTH);
        return true;
    }
    const bool *m = a->color_buffer.mask;
    if (m[0] && m[1] && m[2])
        return false;
    if (m[0] || m[1] || m[2]) {
        interp_note(ip, DIAG_NOTE_COLOR_MASK);
        return false;
    }
    if (ip->stencil.write) { /* a stencil pass: kept for its region */
        ip->stencil.only = true;
        return false;
    }
    if (a->caps[INTERP_CAP_DEPTH_TEST] && a->depth.mask)
        interp_note(ip, DIAG_NOTE_DEPTH_ONLY);
    return true;
}

static bool flat_content(const interp *ip)
{
    const scene *s = ip->scene;
    if (!s || !ip->cleared || ip->frame_begin || ip->accum.active || s->fog.on || s->nsolids ||
        s->ninstances || s->nprotos || ip->nclear_rects || s->nstencil)
        return false;
    for (size_t i = 0; i < s->nmeshes; i++) {
        const scene_look *l = &s->meshes[i].look;
        if (l->lit || l->texture >= 0 || l->texture1 >= 0 || l->blend != SCENE_BLEND_OPAQUE ||
            l->fog || l->material >= 0)
            return false;
    }
    return true;
}

bool interp_masks_clear(interp *ip)
{
    const gl_attribs *a = &ip->st.a;
    const bool *m = a->color_buffer.mask;
    if (!flat_content(ip))
        return false;
    scene *s = ip->scene;
    const float *c = a->color_buffer.clear;
    for (int k = 0; k < 3; k++) {
        if (!m[k])
            continue;
        float v = clamp01(c[k]);
        s->background[k] = v;
        for (size_t i = 0; i < s->nverts; i++)
            s->verts[i].color[k] = v;
        for (size_t i = 0; i < s->nlines; i++)
            for (int j = 0; j < 4; j++)
                s->lines[i].color[j][k] = v;
        for (size_t i = 0; i < s->npoints; i++)
            s->points[i].color[k] = v;
        uint8_t b = (uint8_t)(v * 255.0f + 0.5f);
        for (size_t i = 0; s->overlay && i < (size_t)s->overlay_w * (size_t)s->overlay_h; i++)
            s->overlay[i * 4 + (size_t)k] = b;
    }
    return true;
}
