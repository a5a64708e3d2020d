/* interp_unrecorded.c: @NotRecorded, the recorder's count of the calls it
 * forwarded to GL without recording (format 1.3). They change nothing in
 * the interpreter's state: the frame keeps the counts for the CLI's
 * once-per-trace report (unrec.h). */
#include "interp_internal.h"

void interp_notrecorded(interp *ip, const rgl_cmd *cmd)
{
    /* Earlier frames replayed for their state only are not reported twice. */
    if (!ip->scene)
        return;
    const rgl_arg *name = &cmd->arg[0];
    /* Out of memory, the calls are still counted, as others. */
    (void)unrec_add(&ip->unrecorded, name->bytes, name->count, cmd->arg[1].v.u, ip->frame_index);
}

const struct unrec_table *interp_unrecorded(const interp *ip) { return &ip->unrecorded; }

void interp_unrecorded_batch(interp *ip) { interp_unrec_use(ip, UNREC_USE_BATCH); }

void interp_unrec_pixel_uses(interp *ip, bool draws, bool reads, bool from_memory)
{
    if (draws)
        interp_unrec_use(ip, UNREC_USE_PIXELS);
    if (reads)
        interp_unrec_use(ip, UNREC_USE_READ);
    if (from_memory)
        interp_unrec_use(ip, UNREC_USE_IMAGES);
}

void interp_unrec_draw_uses(interp *ip, GLenum mode)
{
    const gl_attribs *a = &ip->st.a;
    const uint8_t *c = a->caps;
    if (c[INTERP_CAP_BLEND])
        interp_unrec_use(ip, UNREC_USE_BLEND);
    if (c[INTERP_CAP_STENCIL_TEST])
        interp_unrec_use(ip, UNREC_USE_STENCIL);
    if (mode == GL_POINTS ||
        (mode > GL_LINE_STRIP && (a->polygon.mode[0] == GL_POINT || a->polygon.mode[1] == GL_POINT)))
        interp_unrec_use(ip, UNREC_USE_POINTS);
    if (c[INTERP_CAP_MULTISAMPLE] && c[INTERP_CAP_SAMPLE_COVERAGE])
        interp_unrec_use(ip, UNREC_USE_SAMPLE_COVERAGE);
}
