/* interp_buffers.c: the colour buffers drawn into (glDrawBuffer, GL 2.1
 * 4.2.1) and the one a frame shows.
 *
 * A double-buffered program shows its back buffer at the swap; a frame
 * ended by glFlush or glFinish (a single-buffered program, or one drawing
 * to its front buffer: translate/driver/frame_front.c) shows the front one.
 * What goes only to the buffer not shown is not in the picture: draws and
 * pixel rectangles into it are left out, and a colour clear of it leaves
 * the scene (depth and stencil are shared, so their clears still count).
 * GL_NONE draws into no colour buffer at all. The recorder gives each
 * glDrawBuffer the context's visual, by which the interpreter refuses what
 * GL refuses (a back buffer in a single-buffered context, right buffers
 * without stereo, auxiliary buffers, which Mesa has none of). Until a
 * glDrawBuffer (or a snapshot's), the draw buffer is the context's
 * default, the one it shows (docs/mapping.md "Silent differences, round 2").
 */
#include "interp_internal.h"

void interp_drawbuffer(interp *ip, const rgl_cmd *cmd)
{
    if (interp_reject_in_begin(ip))
        return;
    GLenum mode = arg_enum(cmd, 0);
    uint32_t visual = (uint32_t)cmd->arg[1].v.u;
    if (visual & 1)
        ip->st.visual = visual;
    visual = ip->st.visual;
    bool known = visual & 1, dbl = visual & 2, stereo = visual & 4;
    bool back = false, right = false;
    switch (mode) {
    case GL_NONE: case GL_FRONT: case GL_LEFT: case GL_FRONT_LEFT: case GL_FRONT_AND_BACK:
        break;
    case GL_BACK: case GL_BACK_LEFT:
        back = true;
        break;
    case GL_RIGHT: case GL_FRONT_RIGHT:
        right = true;
        break;
    case GL_BACK_RIGHT:
        back = right = true;
        break;
    case GL_AUX0: case GL_AUX1: case GL_AUX2: case GL_AUX3:
        interp_bad_op(ip, "glDrawBuffer of an auxiliary buffer (there are none)");
        return;
    default:
        /* GL_COLOR_ATTACHMENTi: a framebuffer object, which the scene does
         * not follow; drawn as into the default one. */
        if (mode >= GL_COLOR_ATTACHMENT0 && mode < GL_COLOR_ATTACHMENT0 + 16) {
            ip->st.a.color_buffer.draw_buffer = INTERP_DRAW_BUFFER_DEFAULT;
            return;
        }
        interp_bad_enum(ip, "draw buffer", mode);
        return;
    }
    if (known && ((back && !dbl) || (right && !stereo))) {
        interp_bad_op(ip, "glDrawBuffer of a buffer the context does not have");
        return;
    }
    ip->st.a.color_buffer.draw_buffer = mode;
}

void interp_set_shown_front(interp *ip, bool front) { ip->show_front = front; }

bool interp_draw_buffer_hidden(const interp *ip)
{
    GLenum b = ip->st.a.color_buffer.draw_buffer;
    if (b == INTERP_DRAW_BUFFER_DEFAULT)
        return false;
    /* A single-buffered context shows its front buffer whatever ended the
     * frame; without a visual (none recorded), a buffer named back means
     * a double-buffered one. */
    bool dbl = ip->st.visual & 1 ? (ip->st.visual & 2) != 0 : true;
    bool front_shown = !dbl || ip->show_front;
    switch (b) {
    case GL_NONE:
        return true;
    case GL_FRONT: case GL_FRONT_LEFT: case GL_FRONT_RIGHT:
        return !front_shown;
    case GL_BACK: case GL_BACK_LEFT: case GL_BACK_RIGHT:
        return front_shown;
    default: /* GL_FRONT_AND_BACK, GL_LEFT, GL_RIGHT */
        return false;
    }
}
