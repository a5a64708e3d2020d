/* interp_multitex.c: texture units (GL 2.1 sections 2.7, 3.8.13, 3.8.16).
 *
 * The active unit's server state stays where the single-unit code reads
 * it (gl_attribs.texture, the texture caps, the texture matrix stack), so
 * glTexEnv, glTexGen, glBindTexture, glEnable and glMatrixMode(GL_TEXTURE)
 * change the active unit without knowing about units; the other units are
 * parked in gl_state.units and swapped in by glActiveTexture. Current
 * coordinates are per unit: unit 0's in gl_attribs.current (glTexCoord is
 * glMultiTexCoord of GL_TEXTURE0), the others' in gl_state.unit_texcoord.
 * A draw takes the first two enabled units (interp_draw_units); the scene
 * holds at most two textures per look, and a third enabled unit is noted.
 * glPushAttrib(GL_TEXTURE_BIT) saves the active unit only.
 */
#include <string.h>

#include "interp_internal.h"

#define UNIT_CAP0 INTERP_CAP_TEXTURE_1D
#define UNIT_NCAPS (INTERP_CAP_TEXTURE_GEN_Q - INTERP_CAP_TEXTURE_1D + 1)

_Static_assert(UNIT_NCAPS == 8, "the unit's caps are TEXTURE_1D .. TEXTURE_GEN_Q");

void interp_multitex_defaults(gl_state *st)
{
    st->active_unit = st->client_unit = 0;
    for (int k = 0; k < INTERP_TEX_UNITS; k++) {
        gl_tex_unit_parked *u = &st->units[k];
        memset(u, 0, sizeof *u);
        u->texture = st->a.texture;
        u->matrix[0] = mat4_identity();
        static const float def[4] = {0, 0, 0, 1};
        memcpy(st->unit_texcoord[k], def, sizeof def);
    }
}

static void park(gl_state *st, uint32_t k)
{
    gl_tex_unit_parked *u = &st->units[k];
    u->texture = st->a.texture;
    memcpy(u->caps, &st->a.caps[UNIT_CAP0], UNIT_NCAPS);
    u->rect = st->a.caps[INTERP_CAP_TEXTURE_RECTANGLE];
    memcpy(u->matrix, st->texture, sizeof u->matrix);
    u->depth = st->depth[INTERP_TEX];
}

static void unpark(gl_state *st, uint32_t k)
{
    const gl_tex_unit_parked *u = &st->units[k];
    st->a.texture = u->texture;
    memcpy(&st->a.caps[UNIT_CAP0], u->caps, UNIT_NCAPS);
    st->a.caps[INTERP_CAP_TEXTURE_RECTANGLE] = u->rect;
    memcpy(st->texture, u->matrix, sizeof u->matrix);
    st->depth[INTERP_TEX] = u->depth;
}

/* The unit GL_TEXTUREi names, or -1 (a GL_INVALID_ENUM, said). */
static int unit_of(interp *ip, GLenum texture)
{
    if (texture < GL_TEXTURE0 || texture >= GL_TEXTURE0 + INTERP_TEX_UNITS) {
        interp_bad_enum(ip, "texture unit", texture);
        return -1;
    }
    return (int)(texture - GL_TEXTURE0);
}

void interp_activetexture(interp *ip, const rgl_cmd *cmd)
{
    if (interp_reject_in_begin(ip))
        return;
    int k = unit_of(ip, arg_enum(cmd, 0));
    if (k < 0 || (uint32_t)k == ip->st.active_unit)
        return;
    park(&ip->st, ip->st.active_unit);
    unpark(&ip->st, (uint32_t)k);
    ip->st.active_unit = (uint32_t)k;
}

void interp_clientactivetexture(interp *ip, const rgl_cmd *cmd)
{
    int k = unit_of(ip, arg_enum(cmd, 0));
    if (k >= 0)
        ip->st.client_unit = (uint32_t)k;
}

void interp_multitexcoord(interp *ip, const rgl_cmd *cmd)
{
    int k = unit_of(ip, arg_enum(cmd, 0));
    if (k < 0)
        return;
    /* The values follow the target argument. */
    const rgl_arg *a = &cmd->arg[1];
    uint32_t n = a->kind == RGL_ARG_SCALAR ? cmd->nargs - 1 : a->count;
    float *tc = k == 0 ? ip->st.a.current.texcoord : ip->st.unit_texcoord[k];
    static const float def[4] = {0, 0, 0, 1};
    for (uint32_t i = 0; i < 4; i++) {
        double v = i >= n ? def[i]
                   : a->kind == RGL_ARG_SCALAR ? arg_num(&cmd->arg[1 + i])
                                               : a->array[i];
        tc[i] = (float)v;
    }
}

interp_tex_unit interp_unit(interp *ip, uint32_t k)
{
    interp_tex_unit v;
    gl_state *st = &ip->st;
    if (k == st->active_unit) {
        v.texture = &st->a.texture;
        v.caps = &st->a.caps[UNIT_CAP0];
        v.matrix = &st->texture[st->depth[INTERP_TEX]];
    } else {
        const gl_tex_unit_parked *u = &st->units[k];
        v.texture = &u->texture;
        v.caps = u->caps;
        v.matrix = &u->matrix[u->depth];
    }
    v.texcoord = k == 0 ? st->a.current.texcoord : st->unit_texcoord[k];
    return v;
}

void interp_draw_units(interp *ip)
{
    int n = 0;
    interp_texture_r_reset(ip); /* a new primitive: its own r range */
    ip->draw_unit[0] = ip->draw_unit[1] = -1;
    for (uint32_t k = 0; k < INTERP_TEX_UNITS; k++) {
        interp_tex_unit u = interp_unit(ip, k);
        if (!u.caps[INTERP_CAP_TEXTURE_1D - UNIT_CAP0] && !u.caps[INTERP_CAP_TEXTURE_2D - UNIT_CAP0] &&
            !u.caps[INTERP_CAP_TEXTURE_3D - UNIT_CAP0] && !interp_texture_rect_on(ip, k) &&
            !u.caps[INTERP_CAP_TEXTURE_CUBE_MAP - UNIT_CAP0])
            continue;
        if (n == 2) {
            interp_note(ip, DIAG_NOTE_MULTITEX);
            break;
        }
        ip->draw_unit[n++] = (int)k;
    }
    if (n > 0)
        interp_unrec_use(ip, UNREC_USE_TEXTURE);
}

void interp_multitex_unbind(interp *ip, uint32_t name)
{
    for (int k = 0; k < INTERP_TEX_UNITS; k++) {
        struct gl_texture_unit *t = &ip->st.units[k].texture;
        if (t->binding_1d == name)
            t->binding_1d = 0;
        if (t->binding_2d == name)
            t->binding_2d = 0;
        if (t->binding_rect == name)
            t->binding_rect = 0;
        if (t->binding_3d == name)
            t->binding_3d = 0;
        if (t->binding_cube == name)
            t->binding_cube = 0;
    }
}
