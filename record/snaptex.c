/* snaptex.c: texture objects and bindings in the frame-start snapshot.
 *
 * Every texture object RayGL saw made -- 1D, 2D, rectangle, 3D, cube map --
 * is re-created from its recorded definition (entry_custom.c keeps them),
 * then each texture unit gets the bindings GL has now, and the enables of
 * the rectangle, 3D and cube-map targets. Only what the context supports is
 * queried (its version and extension strings), so the snapshot raises no
 * GL error in the host program (STYLE.md, section 4).
 */
#include <stdio.h>
#include <string.h>

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
static bool gl_has(int major, int minor, const char *ext)
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
    return gl_has(1, 3, "GL_ARB_multitexture");
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

void rgl_snap_textures(rgl_stream *s, rgl_buf *b)
{
    bool has[RGL_TEX_TARGETS] = {
        true,
        true,
        gl_has(3, 1, "GL_ARB_texture_rectangle") || gl_has(3, 1, "GL_NV_texture_rectangle"),
        gl_has(1, 2, "GL_EXT_texture3D"),
        gl_has(1, 3, "GL_ARB_texture_cube_map"),
    };
    bool multi = has_multitexture();
    /* While GL compiles a list, glBindTexture and glActiveTexture would go
     * into it: then other units' bindings come from tracking, and their
     * enables are left as GL's initial ones. */
    GLint list = 0;
    glGetIntegerv(GL_LIST_INDEX, &list);
    bool may_bind = list == 0;
    uint32_t active = rgl_tex_active_unit(s), units = 1;
    if (multi) {
        GLint n = 1;
        glGetIntegerv(GL_MAX_TEXTURE_UNITS, &n);
        units = n < 1 ? 1 : n > RGL_MAX_TEX_UNITS ? RGL_MAX_TEX_UNITS : (uint32_t)n;
        if (active >= units)
            active = 0;
    }
    uint32_t bound[RGL_MAX_TEX_UNITS][RGL_TEX_TARGETS];
    bool on[RGL_MAX_TEX_UNITS][RGL_TEX_TARGETS];
    memset(on, 0, sizeof on);
    for (uint32_t u = 0; u < units; u++) {
        bool live = u == active || may_bind;
        if (multi && may_bind)
            glActiveTexture(GL_TEXTURE0 + u);
        for (int k = 0; k < RGL_TEX_TARGETS; k++) {
            bound[u][k] = s->objs.bound[u][k];
            if (!has[k] || !live)
                continue;
            GLint v = 0;
            glGetIntegerv(binding_pnames[k], &v);
            bound[u][k] = (uint32_t)v;
            /* 1D and 2D enables are snapshot.c's. */
            on[u][k] = k >= RGL_TEX_SLOT_RECT && glIsEnabled(tex_targets[k]);
        }
    }
    if (multi && may_bind)
        glActiveTexture(GL_TEXTURE0 + active);

    for (size_t t = 0; t < s->objs.ntextures; t++) {
        const rgl_texture *tex = &s->objs.textures[t];
        int slot = rgl_tex_slot(tex->target);
        if (slot >= 0 && has[slot])
            snap_object(b, tex, may_bind);
    }
    if (may_bind)
        for (int k = 0; k < RGL_TEX_TARGETS; k++)
            if (has[k])
                glBindTexture(tex_targets[k], bound[active][k]);

    /* Replayed from GL's initial state, where unit 0 is active. */
    for (uint32_t u = 0; u < units; u++) {
        if (multi)
            rgl_emit(b, RGL_OP_ActiveTexture, "e", GL_TEXTURE0 + u);
        for (int k = 0; k < RGL_TEX_TARGETS; k++) {
            if (!has[k])
                continue;
            rgl_emit(b, RGL_OP_BindTexture, "ee", tex_targets[k], bound[u][k]);
            if (on[u][k])
                rgl_emit(b, RGL_OP_Enable, "e", tex_targets[k]);
        }
    }
    if (multi)
        rgl_emit(b, RGL_OP_ActiveTexture, "e", GL_TEXTURE0 + active);
}
