/* interp_select.c: render modes and the name stack (GL 1.x 5.2, 5.3):
 * glRenderMode, glSelectBuffer, glFeedbackBuffer, glInitNames,
 * glPushName, glLoadName, glPopName, glPassThrough.
 *
 * In GL_SELECT and GL_FEEDBACK mode GL rasterises nothing: what is drawn
 * goes to the program's buffer as hits or feedback, not to the picture.
 * The draws check interp_render_mode_draws and leave it out (a picking pass
 * before the real draw would otherwise show). A clear does nothing then
 * either (Mesa clears only in GL_RENDER mode).
 *
 * GL keeps the name stack only in GL_SELECT mode and ignores the name
 * calls in the others. A program usually makes the same calls in its
 * render pass, so the interpreter keeps them there too, as labels: each
 * mesh and solid drawn in GL_RENDER mode carries the stack current at its
 * draw (scene_look.names), and the writer names it in the SDL. In
 * GL_SELECT mode the calls are checked as GL checks them; in the others a
 * call GL would reject there is ignored silently, as GL ignores all of
 * them. GL empties the stack when GL_SELECT mode ends.
 */
#include "interp_internal.h"

static bool buffer_size_ok(interp *ip, const rgl_cmd *cmd)
{
    if (rgl_arg_i(&cmd->arg[0], 0) < 0) {
        interp_bad_value(ip, "negative buffer size");
        return false;
    }
    return true;
}

void interp_selectbuffer(interp *ip, const rgl_cmd *cmd)
{
    if (ip->st.render_mode == GL_SELECT) {
        interp_bad_op(ip, "glSelectBuffer in GL_SELECT mode");
        return;
    }
    if (buffer_size_ok(ip, cmd))
        ip->st.select_size = (int32_t)rgl_arg_i(&cmd->arg[0], 0);
}

void interp_feedbackbuffer(interp *ip, const rgl_cmd *cmd)
{
    GLenum type = arg_enum(cmd, 1);
    if (ip->st.render_mode == GL_FEEDBACK) {
        interp_bad_op(ip, "glFeedbackBuffer in GL_FEEDBACK mode");
        return;
    }
    if (!buffer_size_ok(ip, cmd))
        return;
    if (type != GL_2D && type != GL_3D && type != GL_3D_COLOR && type != GL_3D_COLOR_TEXTURE &&
        type != GL_4D_COLOR_TEXTURE) {
        interp_bad_enum(ip, "feedback type", type);
        return;
    }
    ip->st.feedback_size = (int32_t)rgl_arg_i(&cmd->arg[0], 0);
}

void interp_rendermode(interp *ip, const rgl_cmd *cmd)
{
    GLenum mode = arg_enum(cmd, 0);
    gl_state *st = &ip->st;
    if (mode != GL_RENDER && mode != GL_SELECT && mode != GL_FEEDBACK) {
        interp_bad_enum(ip, "render mode", mode);
        return;
    }
    /* Without a buffer of a size above 0 Mesa reports GL_INVALID_OPERATION
     * and still enters the mode (checked with OSMesa): nothing is drawn. */
    if ((mode == GL_SELECT && st->select_size <= 0) ||
        (mode == GL_FEEDBACK && st->feedback_size <= 0))
        interp_bad_op(ip, mode == GL_SELECT ? "GL_SELECT mode without glSelectBuffer"
                                            : "GL_FEEDBACK mode without glFeedbackBuffer");
    if (st->render_mode == GL_SELECT)
        st->nnames = 0;
    st->render_mode = mode;
}

bool interp_render_mode_draws(interp *ip)
{
    if (ip->st.render_mode == GL_RENDER)
        return true;
    if (ip->scene)
        interp_note_held(ip, DIAG_NOTE_RENDER_MODE, "OpenGL draws none of it either");
    return false;
}

uint32_t interp_names_for_draw(interp *ip)
{
    if (!ip->scene || ip->st.nnames <= 0)
        return 0;
    return scene_names_index(ip->scene, ip->st.names, (uint32_t)ip->st.nnames);
}

void interp_initnames(interp *ip, const rgl_cmd *cmd)
{
    (void)cmd;
    ip->st.nnames = 0;
}

void interp_pushname(interp *ip, const rgl_cmd *cmd)
{
    gl_state *st = &ip->st;
    if (st->nnames >= INTERP_MAX_NAME_STACK) {
        if (st->render_mode == GL_SELECT)
            interp_diag(ip, DIAG_GL_STACK_OVERFLOW, "name stack overflow");
        return;
    }
    st->names[st->nnames++] = (uint32_t)cmd->arg[0].v.u;
}

void interp_loadname(interp *ip, const rgl_cmd *cmd)
{
    gl_state *st = &ip->st;
    if (st->nnames <= 0) {
        if (st->render_mode == GL_SELECT)
            interp_bad_op(ip, "glLoadName with an empty name stack");
        return;
    }
    st->names[st->nnames - 1] = (uint32_t)cmd->arg[0].v.u;
}

void interp_popname(interp *ip, const rgl_cmd *cmd)
{
    (void)cmd;
    gl_state *st = &ip->st;
    if (st->nnames <= 0) {
        if (st->render_mode == GL_SELECT)
            interp_diag(ip, DIAG_GL_STACK_UNDERFLOW, "name stack underflow");
        return;
    }
    st->nnames--;
}

/* A marker in the feedback buffer: nothing to draw in any mode. */
void interp_passthrough(interp *ip, const rgl_cmd *cmd)
{
    (void)ip;
    (void)cmd;
}
