/* interp_later.c: textures, display lists, vertex arrays, GLU quadrics and
 * GLUT solids: issue 5.
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
void interp_glusphere(interp *ip, const rgl_cmd *cmd) { (void)cmd; skip_draw(ip, DIAG_NOTE_QUADRICS); }
void interp_glucylinder(interp *ip, const rgl_cmd *cmd) { (void)cmd; skip_draw(ip, DIAG_NOTE_QUADRICS); }
void interp_gludisk(interp *ip, const rgl_cmd *cmd) { (void)cmd; skip_draw(ip, DIAG_NOTE_QUADRICS); }
void interp_glupartialdisk(interp *ip, const rgl_cmd *cmd) { (void)cmd; skip_draw(ip, DIAG_NOTE_QUADRICS); }
void interp_glutsphere(interp *ip, const rgl_cmd *cmd) { (void)cmd; skip_draw(ip, DIAG_NOTE_GLUT); }
void interp_glutcube(interp *ip, const rgl_cmd *cmd) { (void)cmd; skip_draw(ip, DIAG_NOTE_GLUT); }
void interp_glutcone(interp *ip, const rgl_cmd *cmd) { (void)cmd; skip_draw(ip, DIAG_NOTE_GLUT); }
void interp_gluttorus(interp *ip, const rgl_cmd *cmd) { (void)cmd; skip_draw(ip, DIAG_NOTE_GLUT); }
void interp_glutteapot(interp *ip, const rgl_cmd *cmd) { (void)cmd; skip_draw(ip, DIAG_NOTE_GLUT); }
void interp_glutpolyhedron(interp *ip, const rgl_cmd *cmd) { (void)cmd; skip_draw(ip, DIAG_NOTE_GLUT); }
void interp_glutcylinder(interp *ip, const rgl_cmd *cmd) { (void)cmd; skip_draw(ip, DIAG_NOTE_GLUT); }

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

/* ---- Textures ------------------------------------------------------------------ */

void interp_gentextures(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_deletetextures(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_teximage1d(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_teximage2d(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_texsubimage2d(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_texparameter(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_texgen(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_pixelstore(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_build2dmipmaps(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }

void interp_bindtexture(interp *ip, const rgl_cmd *cmd)
{
    GLenum target = arg_enum(cmd, 0);
    uint32_t name = (uint32_t)cmd->arg[1].v.u;
    if (target == GL_TEXTURE_1D)
        ip->st.a.texture.binding_1d = name;
    else if (target == GL_TEXTURE_2D)
        ip->st.a.texture.binding_2d = name;
}

void interp_texenv(interp *ip, const rgl_cmd *cmd)
{
    GLenum pname = arg_enum(cmd, 1);
    if (pname == GL_TEXTURE_ENV_MODE && cmd->arg[2].kind == RGL_ARG_SCALAR)
        ip->st.a.texture.env_mode = (GLenum)arg_num(&cmd->arg[2]);
}

/* ---- GLU quadric objects -------------------------------------------------------- */

void interp_newquadric(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_deletequadric(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_quadricdrawstyle(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_quadricnormals(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_quadricorientation(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_quadrictexture(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
