/* interp_scissor.c: the scissor test (GL 1.x 4.1.2): glScissor, and what
 * a scissored clear does to the scene.
 *
 * The box is an attribute (GL_SCISSOR_BIT); until the first glScissor it
 * is the whole window, which a trace does not hold, so an unset box
 * scissors nothing.
 */
#include "interp_internal.h"

void interp_scissor(interp *ip, const rgl_cmd *cmd)
{
    int64_t w = rgl_arg_i(&cmd->arg[2], 0), h = rgl_arg_i(&cmd->arg[3], 0);
    if (w < 0 || h < 0) {
        interp_bad_value(ip, "negative scissor size");
        return;
    }
    int32_t *b = ip->st.a.scissor.box;
    b[0] = (int32_t)rgl_arg_i(&cmd->arg[0], 0);
    b[1] = (int32_t)rgl_arg_i(&cmd->arg[1], 0);
    b[2] = (int32_t)w;
    b[3] = (int32_t)h;
    ip->st.a.scissor.set = true;
}
