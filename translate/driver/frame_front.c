/* frame_front.c: what a single-buffered frame shows.
 *
 * A program drawing into the front buffer shows its picture at glFlush or
 * glFinish, and the recorder ends a frame there (record/preload.c). The
 * front buffer then holds everything drawn since the last colour clear,
 * in this frame or earlier ones: a frame that only flushes still shows
 * the earlier drawing. frame.c replays those earlier frames' drawing
 * before the frame's own; this file reads a frame's commands to find where
 * that chain starts (docs/mapping.md "Projections, depth and draw order").
 * A clear while glDrawBuffer names only back buffers (or none) leaves the
 * front buffer as it was.
 */
#include "frame_front.h"

#include <GL/gl.h>

front_scan front_scan_frame(const rgl_frame_info *fi)
{
    front_scan r = {false, false};
    bool back_only = false; /* glDrawBuffer names no front buffer (interp_buffers.c) */
    rgl_cmd_iter it;
    rgl_cmd_iter_init(&it, fi->commands, fi->commands_size, fi->commands_offset);
    rgl_cmd cmd;
    for (;;) {
        /* Vertices, normals and colours are most of a frame: stepped over. */
        if (rgl_cmd_skip_float_run(&it)) {
            r.flushed = false;
            continue;
        }
        if (rgl_cmd_next(&it, &cmd) != RGL_OK)
            break;
        const rgl_cmd_info *info = cmd.info;
        if (!info || info->api == RGL_API_REC || info->opcode == RGL_OP_FrameEnd)
            continue;
        r.flushed = info->opcode == RGL_OP_Flush || info->opcode == RGL_OP_Finish;
        if (info->opcode == RGL_OP_DrawBuffer) {
            uint32_t b = (uint32_t)rgl_arg_i(&cmd.arg[0], 0);
            back_only = b == GL_BACK || b == GL_BACK_LEFT || b == GL_BACK_RIGHT || b == GL_NONE;
        }
        if (info->opcode == RGL_OP_Clear && (rgl_arg_i(&cmd.arg[0], 0) & GL_COLOR_BUFFER_BIT) &&
            !back_only)
            r.clears_color = true;
    }
    return r;
}
