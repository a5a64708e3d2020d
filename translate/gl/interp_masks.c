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
