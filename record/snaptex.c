/* snaptex.c: texture objects and texture units in the frame-start snapshot.
 *
 * Every texture object RayGL saw made -- 1D, 2D, rectangle, 3D, cube map --
 * is re-created from its recorded definition (entry_custom.c keeps them),
 * then each texture unit gets one block after one glActiveTexture: its
 * enables, environment, texgen, bindings, current coordinates and texture
 * matrix as GL has them now. Only what the context supports is
 * queried (its version and extension strings), so the snapshot raises no
 * GL error in the host program (STYLE.md, section 4).
 */
#include <stdio.h>
#include <string.h>

#define GL_GLEXT_PROTOTYPES 1 /* glActiveTexture (GL 1.3) */
#include <GL/gl.h>
#include <GL/glext.h>

#include "recorder.h"

#define SENTINEL_I 0x7ead7ead

static const GLenum tex_targets[RGL_TEX_TARGETS] = {
    GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP,
};
static const GLenum binding_pnames[RGL_TEX_TARGETS] = {
    GL_TEXTURE_BINDING_1D, GL_TEXTURE_BINDING_2D, GL_TEXTURE_BINDING_RECTANGLE_ARB,
    GL_TEXTURE_BINDING_3D, GL_TEXTURE_BINDING_CUBE_MAP,
};

/* Texture parameters read back from GL (the rest come from tracking). */
static const GLenum tex_params_live[] = {GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER,
                                         GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T};

int rgl_tex_slot(uint32_t target)
{
    if (target >= GL_TEXTURE_CUBE_MAP_POSITIVE_X && target <= GL_TEXTURE_CUBE_MAP_NEGATIVE_Z)
        return RGL_TEX_SLOT_CUBE;
    for (int k = 0; k < RGL_TEX_TARGETS; k++)
        if (tex_targets[k] == target)
            return k;
    return -1;
}

uint32_t rgl_tex_slot_target(int slot)
{
    return slot >= 0 && slot < RGL_TEX_TARGETS ? tex_targets[slot] : 0;
}

/* Whether the current context is GL major.minor or later, or lists
 * extension ext (a whole name). False without a context. */
bool rgl_gl_has(int major, int minor, const char *ext)
{
    const char *v = (const char *)glGetString(GL_VERSION);
    int ma = 0, mi = 0;
    if (!v)
        return false;
    if (sscanf(v, "%d.%d", &ma, &mi) == 2 && (ma > major || (ma == major && mi >= minor)))
        return true;
    const char *e = (const char *)glGetString(GL_EXTENSIONS);
    size_t n = strlen(ext);
    for (const char *p = e; p && (p = strstr(p, ext)) != NULL; p += n)
        if ((p == e || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0'))
            return true;
    return false;
}

static bool has_multitexture(void)
{
    return rgl_gl_has(1, 3, "GL_ARB_multitexture");
}

uint32_t rgl_tex_active_unit(const rgl_stream *s)
{
    /* glGet* between glBegin and glEnd is an error GL would report. */
    if (s->in_begin || !has_multitexture())
        return 0;
    GLint a = SENTINEL_I;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &a);
    uint32_t u = (uint32_t)a - GL_TEXTURE0;
    return a != SENTINEL_I && u < RGL_MAX_TEX_UNITS ? u : 0;
}

static bool is_live_param(uint32_t pname)
{
    for (size_t k = 0; k < sizeof tex_params_live / sizeof tex_params_live[0]; k++)
        if (tex_params_live[k] == pname)
            return true;
    return false;
}

/* One texture object: bind, its images (resource ids), its parameters;
 * the live ones read back with the object bound on the active unit. */
static void snap_object(rgl_buf *b, const rgl_texture *tex, bool may_bind)
{
    rgl_emit(b, RGL_OP_BindTexture, "ee", tex->target, tex->name);
    if (tex->defs.size) {
        uint8_t *p = rgl_buf_reserve(b, tex->defs.size);
        if (p)
            rgl_buf_commit(b, (uint8_t *)memcpy(p, tex->defs.data, tex->defs.size) +
                                  tex->defs.size);
    }
    for (uint32_t k = 0; k < tex->nparams; k++) {
        const rgl_tex_param *pr = &tex->params[k];
        if (is_live_param(pr->pname))
            continue;
        if (pr->is_float)
            rgl_emit(b, RGL_OP_TexParameterfv, "eeN", tex->target, pr->pname, pr->f,
                     (int)pr->count);
        else
            rgl_emit(b, RGL_OP_TexParameteriv, "eeI", tex->target, pr->pname, pr->i,
                     (int)pr->count);
    }
    /* A name deleted behind RayGL's back is not re-created by binding. */
    if (!may_bind || (tex->name != 0 && !glIsTexture(tex->name)))
        return;
    glBindTexture(tex->target, tex->name);
    for (size_t k = 0; k < sizeof tex_params_live / sizeof tex_params_live[0]; k++) {
        GLint v = SENTINEL_I;
        glGetTexParameteriv(tex->target, tex_params_live[k], &v);
        if (v != SENTINEL_I)
            rgl_emit(b, RGL_OP_TexParameteri, "eei", tex->target, tex_params_live[k], v);
    }
}

static const GLenum texgen_coords[4] = {GL_S, GL_T, GL_R, GL_Q};

static bool all_equal(const GLfloat *v, const GLfloat *w, int n)
{
    for (int k = 0; k < n; k++)
        if (v[k] != w[k])
            return false;
    return true;
}

/* The active unit's environment and texgen, only what differs from GL's
 * initial state (the replay starts from it). */
static void snap_texenv(rgl_buf *b)
{
    static const GLfloat zero[4] = {0, 0, 0, 0};
    GLint mode = GL_MODULATE;
    GLfloat color[4] = {0};
    glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &mode);
    glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, color);
    if (mode != GL_MODULATE)
        rgl_emit(b, RGL_OP_TexEnvi, "eei", GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, mode);
    if (!all_equal(color, zero, 4))
        rgl_emit(b, RGL_OP_TexEnvfv, "eeN", GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, color, 4);
    if (mode == GL_COMBINE) { /* the combiner (GL 1.3), only where it is used */
        static const GLenum ipn[] = {GL_COMBINE_RGB, GL_COMBINE_ALPHA, GL_SOURCE0_RGB,
                                     GL_SOURCE1_RGB, GL_SOURCE2_RGB, GL_OPERAND0_RGB,
                                     GL_OPERAND1_RGB, GL_OPERAND2_RGB, GL_SOURCE0_ALPHA,
                                     GL_SOURCE1_ALPHA, GL_SOURCE2_ALPHA, GL_OPERAND0_ALPHA,
                                     GL_OPERAND1_ALPHA, GL_OPERAND2_ALPHA};
        for (size_t k = 0; k < sizeof ipn / sizeof ipn[0]; k++) {
            GLint v = SENTINEL_I;
            glGetTexEnviv(GL_TEXTURE_ENV, ipn[k], &v);
            if (v != SENTINEL_I)
                rgl_emit(b, RGL_OP_TexEnvi, "eei", GL_TEXTURE_ENV, ipn[k], v);
        }
        static const GLenum fpn[] = {GL_RGB_SCALE, GL_ALPHA_SCALE};
        for (size_t k = 0; k < 2; k++) {
            GLfloat f = 1;
            glGetTexEnvfv(GL_TEXTURE_ENV, fpn[k], &f);
            rgl_emit(b, RGL_OP_TexEnvf, "eef", GL_TEXTURE_ENV, fpn[k], (double)f);
        }
    }
    /* The unit's level-of-detail bias (GL 1.4) and point-sprite coordinate
     * replacement (GL 2.0), where the context has them. */
    if (rgl_gl_has(1, 4, "GL_EXT_texture_lod_bias")) {
        GLfloat bias = 0;
        glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, &bias);
        if (bias != 0)
            rgl_emit(b, RGL_OP_TexEnvf, "eef", GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS,
                     (double)bias);
    }
    if (rgl_gl_has(2, 0, "GL_ARB_point_sprite")) {
        GLint replace = GL_FALSE;
        glGetTexEnviv(GL_POINT_SPRITE, GL_COORD_REPLACE, &replace);
        if (replace)
            rgl_emit(b, RGL_OP_TexEnvi, "eei", GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
    }
    /* GL keeps eye planes in eye space: under the snapshot's identity
     * modelview they go in as read back. */
    static const GLfloat initial_plane[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0}, {0}};
    for (int c = 0; c < 4; c++) {
        GLint gm = GL_EYE_LINEAR;
        GLfloat obj[4], eye[4];
        memcpy(obj, initial_plane[c], sizeof obj);
        memcpy(eye, initial_plane[c], sizeof eye);
        glGetTexGeniv(texgen_coords[c], GL_TEXTURE_GEN_MODE, &gm);
        glGetTexGenfv(texgen_coords[c], GL_OBJECT_PLANE, obj);
        glGetTexGenfv(texgen_coords[c], GL_EYE_PLANE, eye);
        if (gm != GL_EYE_LINEAR)
            rgl_emit(b, RGL_OP_TexGeni, "eei", texgen_coords[c], GL_TEXTURE_GEN_MODE, gm);
        if (!all_equal(obj, initial_plane[c], 4))
            rgl_emit(b, RGL_OP_TexGenfv, "eeN", texgen_coords[c], GL_OBJECT_PLANE, obj, 4);
        if (!all_equal(eye, initial_plane[c], 4))
            rgl_emit(b, RGL_OP_TexGenfv, "eeN", texgen_coords[c], GL_EYE_PLANE, eye, 4);
    }
}

/* What the snapshot knows of the context's texturing. */
typedef struct {
    bool has[RGL_TEX_TARGETS]; /* targets the context supports */
    bool multi;                /* glActiveTexture (GL 1.3, ARB_multitexture) */
    bool may_bind;             /* no list being compiled */
    uint32_t active, units;
    uint32_t replay[RGL_TEX_TARGETS]; /* unit 0's bindings in the replay so far */
    bool texture_mode;                /* the replay's matrix mode is GL_TEXTURE */
} snap_units;

/* Unit u's block, read from GL with u the active unit: enables, environment,
 * texgen, bindings, current coordinates, texture matrix; each only where it
 * differs from what the replay has. */
static void snap_unit_live(rgl_buf *b, snap_units *su, uint32_t u)
{
    static const GLenum gen_caps[4] = {GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R,
                                       GL_TEXTURE_GEN_Q};
    for (int k = 0; k < RGL_TEX_TARGETS; k++)
        if (su->has[k] && glIsEnabled(tex_targets[k]))
            rgl_emit(b, RGL_OP_Enable, "e", tex_targets[k]);
    for (int c = 0; c < 4; c++)
        if (glIsEnabled(gen_caps[c]))
            rgl_emit(b, RGL_OP_Enable, "e", gen_caps[c]);
    snap_texenv(b);
    for (int k = 0; k < RGL_TEX_TARGETS; k++) {
        if (!su->has[k])
            continue;
        GLint v = 0;
        glGetIntegerv(binding_pnames[k], &v);
        if ((uint32_t)v != (u == 0 ? su->replay[k] : 0))
            rgl_emit(b, RGL_OP_BindTexture, "ee", tex_targets[k], (uint32_t)v);
    }
    static const GLfloat t0[4] = {0, 0, 0, 1};
    GLfloat t[4] = {0, 0, 0, 1};
    glGetFloatv(GL_CURRENT_TEXTURE_COORDS, t);
    if (!all_equal(t, t0, 4)) {
        if (su->multi) /* glTexCoord is unit 0's: the unit named */
            rgl_emit(b, RGL_OP_MultiTexCoord4f, "effff", GL_TEXTURE0 + u, (double)t[0],
                     (double)t[1], (double)t[2], (double)t[3]);
        else
            rgl_emit(b, RGL_OP_TexCoord4f, "ffff", (double)t[0], (double)t[1], (double)t[2],
                     (double)t[3]);
    }
    static const GLfloat id[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    GLfloat m[16];
    memcpy(m, id, sizeof m);
    glGetFloatv(GL_TEXTURE_MATRIX, m);
    if (!all_equal(m, id, 16)) {
        if (!su->texture_mode)
            rgl_emit(b, RGL_OP_MatrixMode, "e", GL_TEXTURE);
        su->texture_mode = true;
        rgl_emit(b, RGL_OP_LoadMatrixf, "A", m, 16);
    }
}

/* A unit GL cannot make active (a list is being compiled): the bindings
 * RayGL tracked; the rest is left as GL's initial state. */
static void snap_unit_tracked(rgl_stream *s, rgl_buf *b, const snap_units *su, uint32_t u)
{
    for (int k = 0; k < RGL_TEX_TARGETS; k++)
        if (su->has[k] && s->objs.bound[u][k] != (u == 0 ? su->replay[k] : 0))
            rgl_emit(b, RGL_OP_BindTexture, "ee", tex_targets[k], s->objs.bound[u][k]);
}

/* The texture objects, then one block per unit in unit order, each after
 * one glActiveTexture naming it (in GL and in the replay, which starts on
 * unit 0), then the program's active unit once, if it is not the last
 * one named. Without multitexture: unit 0's block alone, no
 * glActiveTexture. The caller restores GL's matrix mode in the replay. */
void rgl_snap_textures(rgl_stream *s, rgl_buf *b)
{
    snap_units su = {
        .has = {true, true,
                rgl_gl_has(3, 1, "GL_ARB_texture_rectangle") ||
                    rgl_gl_has(3, 1, "GL_NV_texture_rectangle"),
                rgl_gl_has(1, 2, "GL_EXT_texture3D"), rgl_gl_has(1, 3, "GL_ARB_texture_cube_map")},
        .multi = has_multitexture(),
        .units = 1,
    };
    /* While GL compiles a list, glBindTexture and glActiveTexture would go
     * into it. */
    GLint list = 0;
    glGetIntegerv(GL_LIST_INDEX, &list);
    su.may_bind = list == 0;
    su.active = rgl_tex_active_unit(s);
    if (su.multi) {
        GLint n = 1;
        glGetIntegerv(GL_MAX_TEXTURE_UNITS, &n);
        su.units = n < 1 ? 1 : n > RGL_MAX_TEX_UNITS ? RGL_MAX_TEX_UNITS : (uint32_t)n;
        if (su.active >= su.units)
            su.active = 0;
    }

    /* The objects, bound on the active unit to read their live parameters;
     * its bindings put back after. */
    GLint active_bound[RGL_TEX_TARGETS] = {0};
    for (int k = 0; k < RGL_TEX_TARGETS; k++)
        if (su.has[k])
            glGetIntegerv(binding_pnames[k], &active_bound[k]);
    bool bound_any = false;
    for (size_t t = 0; t < s->objs.ntextures; t++) {
        const rgl_texture *tex = &s->objs.textures[t];
        int slot = rgl_tex_slot(tex->target);
        if (slot < 0 || !su.has[slot])
            continue;
        snap_object(b, tex, su.may_bind);
        su.replay[slot] = tex->name;
        bound_any = true;
    }
    if (su.may_bind && bound_any)
        for (int k = 0; k < RGL_TEX_TARGETS; k++)
            if (su.has[k])
                glBindTexture(tex_targets[k], (GLuint)active_bound[k]);

    if (!su.multi) {
        snap_unit_live(b, &su, 0);
        return;
    }
    uint32_t last = 0;
    for (uint32_t u = 0; u < su.units; u++) {
        bool live = su.may_bind || u == su.active;
        if (su.may_bind)
            glActiveTexture(GL_TEXTURE0 + u);
        rgl_emit(b, RGL_OP_ActiveTexture, "e", GL_TEXTURE0 + u);
        last = u;
        if (live)
            snap_unit_live(b, &su, u);
        else
            snap_unit_tracked(s, b, &su, u);
    }
    if (last != su.active) {
        if (su.may_bind)
            glActiveTexture(GL_TEXTURE0 + su.active);
        rgl_emit(b, RGL_OP_ActiveTexture, "e", GL_TEXTURE0 + su.active);
    }
}
