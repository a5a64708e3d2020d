/* interp_later.c: display lists and vertex arrays: issue 5 (shapes are
 * in interp_shape.c, textures in interp_texture.c).
 *
 * Each handler already sits where issue 5 fills it in. Until then the
 * draws are skipped with a note said once per kind, and the state calls
 * are accepted without effect (a texture binding, a pointer), so nothing
 * crashes and no broken SDL is written. glListBase is kept: it is context
 * state that frames carry.
 */
#include "interp_internal.h"

/* ---- Draws: noted, skipped ------------------------------------------------------ */

static void skip_draw(interp *ip, diag_kind note)
{
    if (ip->scene)
        interp_note(ip, note);
}

void interp_calllist(interp *ip, const rgl_cmd *cmd) { (void)cmd; skip_draw(ip, DIAG_NOTE_LISTS); }
void interp_calllists(interp *ip, const rgl_cmd *cmd) { (void)cmd; skip_draw(ip, DIAG_NOTE_LISTS); }
void interp_arrayelement(interp *ip, const rgl_cmd *cmd) { (void)cmd; skip_draw(ip, DIAG_NOTE_ARRAYS); }
void interp_drawarrays(interp *ip, const rgl_cmd *cmd) { (void)cmd; skip_draw(ip, DIAG_NOTE_ARRAYS); }
void interp_drawelements(interp *ip, const rgl_cmd *cmd) { (void)cmd; skip_draw(ip, DIAG_NOTE_ARRAYS); }
void interp_drawrangeelements(interp *ip, const rgl_cmd *cmd) { (void)cmd; skip_draw(ip, DIAG_NOTE_ARRAYS); }

/* ---- Display lists ------------------------------------------------------------- */

void interp_genlists(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_deletelists(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_endlist(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }

/* GL_COMPILE_AND_EXECUTE bodies travel only in the list resource, so until
 * issue 5 replays them, say that they were not drawn. */
void interp_newlist(interp *ip, const rgl_cmd *cmd)
{
    GLenum mode = arg_enum(cmd, 1);
    if (mode != GL_COMPILE && mode != GL_COMPILE_AND_EXECUTE) {
        interp_bad_enum(ip, "list mode", mode);
        return;
    }
    if (mode == GL_COMPILE_AND_EXECUTE)
        skip_draw(ip, DIAG_NOTE_LISTS);
}

void interp_listbase(interp *ip, const rgl_cmd *cmd)
{
    ip->st.list_base = (uint32_t)cmd->arg[0].v.u;
}

/* ---- Vertex arrays ------------------------------------------------------------- */

void interp_vertexpointer(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_normalpointer(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_colorpointer(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_texcoordpointer(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_edgeflagpointer(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_interleavedarrays(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_enableclientstate(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_disableclientstate(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_arraydata(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
