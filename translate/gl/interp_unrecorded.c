/* interp_unrecorded.c: @NotRecorded, the recorder's count of the calls it
 * forwarded to GL without recording (format 1.3). They change nothing in
 * the interpreter's state: the frame keeps the counts for the CLI's
 * once-per-trace report (unrecorded.h). */
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
