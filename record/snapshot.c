/* snapshot.c: the resolved-state snapshot taken at the start of a frame.
 *
 * With a live GL context, the state that affects what a frame shows is read
 * back with glGet* and encoded as ordinary commands that, replayed from GL's
 * default state, reproduce it. The recorder stores the result as a
 * deduplicated resource that the frame references, so each frame can be
 * translated without the frames before it (docs/design.md, "Resolved state").
 *
 * Only side-effect-free queries are used, except for the texture part
 * (snaptex.c): texture objects are bound to read their parameters, and
 * each texture unit made active in turn to read its state; what GL had is
 * restored.
 */
#include <string.h>

#define GL_GLEXT_PROTOTYPES 1 /* glBindBuffer (GL 1.5): the stipple read-back sets the pack buffer aside */
#include <GL/gl.h>
#include <GL/glext.h>

#include "recorder.h"

#define SENTINEL_I 0x7ead7ead

static const GLenum light_names[8] = {GL_LIGHT0, GL_LIGHT1, GL_LIGHT2, GL_LIGHT3,
                                      GL_LIGHT4, GL_LIGHT5, GL_LIGHT6, GL_LIGHT7};

/* Capabilities that change what a frame shows, all off by default (the
 * texture units' are snaptex.c's). */
static const GLenum caps_off[] = {
    GL_LIGHTING, GL_LIGHT0, GL_LIGHT1, GL_LIGHT2, GL_LIGHT3, GL_LIGHT4, GL_LIGHT5, GL_LIGHT6,
    GL_LIGHT7, GL_COLOR_MATERIAL, GL_CULL_FACE, GL_DEPTH_TEST, GL_BLEND, GL_ALPHA_TEST, GL_FOG,
    GL_NORMALIZE, GL_RESCALE_NORMAL, GL_POLYGON_OFFSET_FILL,
    GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT, GL_LINE_SMOOTH, GL_POINT_SMOOTH,
    GL_POLYGON_SMOOTH, GL_AUTO_NORMAL, GL_MAP1_COLOR_4, GL_MAP1_INDEX, GL_MAP1_NORMAL,
    GL_MAP1_TEXTURE_COORD_1, GL_MAP1_TEXTURE_COORD_2, GL_MAP1_TEXTURE_COORD_3,
    GL_MAP1_TEXTURE_COORD_4, GL_MAP1_VERTEX_3, GL_MAP1_VERTEX_4, GL_MAP2_COLOR_4, GL_MAP2_INDEX,
    GL_MAP2_NORMAL, GL_MAP2_TEXTURE_COORD_1, GL_MAP2_TEXTURE_COORD_2, GL_MAP2_TEXTURE_COORD_3,
    GL_MAP2_TEXTURE_COORD_4, GL_MAP2_VERTEX_3, GL_MAP2_VERTEX_4, GL_POLYGON_STIPPLE,
    GL_COLOR_LOGIC_OP, GL_SCISSOR_TEST,
};

static GLint get_i(GLenum pname)
{
    GLint v[4] = {0, 0, 0, 0};
    glGetIntegerv(pname, v);
    return v[0];
}

static GLfloat get_f(GLenum pname)
{
    GLfloat v[16] = {0};
    glGetFloatv(pname, v);
    return v[0];
}

static void snap_lights_eye(rgl_buf *b)
{
    /* GL keeps light positions and spot directions in eye space
     * (transformed by the modelview current at the glLight call):
     * replayed under an identity modelview they stay as read back. */
    for (int l = 0; l < 8; l++) {
        GLfloat v[4] = {0, 0, 1, 0};
        glGetLightfv(light_names[l], GL_POSITION, v);
        rgl_emit(b, RGL_OP_Lightfv, "eeN", light_names[l], GL_POSITION, v, 4);
        GLfloat d[4] = {0, 0, -1, 0};
        glGetLightfv(light_names[l], GL_SPOT_DIRECTION, d);
        rgl_emit(b, RGL_OP_Lightfv, "eeN", light_names[l], GL_SPOT_DIRECTION, d, 3);
    }
}

static void snap_lights(rgl_buf *b)
{
    static const GLenum colors[3] = {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR};
    static const GLenum scalars[5] = {GL_SPOT_EXPONENT, GL_SPOT_CUTOFF, GL_CONSTANT_ATTENUATION,
                                      GL_LINEAR_ATTENUATION, GL_QUADRATIC_ATTENUATION};
    for (int l = 0; l < 8; l++) {
        for (int k = 0; k < 3; k++) {
            GLfloat v[4] = {0};
            glGetLightfv(light_names[l], colors[k], v);
            rgl_emit(b, RGL_OP_Lightfv, "eeN", light_names[l], colors[k], v, 4);
        }
        for (int k = 0; k < 5; k++) {
            GLfloat v[4] = {0};
            glGetLightfv(light_names[l], scalars[k], v);
            rgl_emit(b, RGL_OP_Lightf, "eef", light_names[l], scalars[k], (double)v[0]);
        }
    }
    GLfloat amb[4] = {0};
    glGetFloatv(GL_LIGHT_MODEL_AMBIENT, amb);
    rgl_emit(b, RGL_OP_LightModelfv, "eN", GL_LIGHT_MODEL_AMBIENT, amb, 4);
    rgl_emit(b, RGL_OP_LightModelf, "ef", GL_LIGHT_MODEL_LOCAL_VIEWER,
             (double)get_f(GL_LIGHT_MODEL_LOCAL_VIEWER));
    rgl_emit(b, RGL_OP_LightModelf, "ef", GL_LIGHT_MODEL_TWO_SIDE,
             (double)get_f(GL_LIGHT_MODEL_TWO_SIDE));
    GLint cc[4] = {SENTINEL_I};
    glGetIntegerv(GL_LIGHT_MODEL_COLOR_CONTROL, cc);
    if (cc[0] != SENTINEL_I && cc[0] != GL_SINGLE_COLOR)
        rgl_emit(b, RGL_OP_LightModeli, "ei", GL_LIGHT_MODEL_COLOR_CONTROL, cc[0]);
}

/* The current colour and normal; each unit's texture coordinates are
 * snaptex.c's. */
static void snap_current(rgl_buf *b)
{
    GLfloat c[4] = {1, 1, 1, 1}, n[4] = {0, 0, 1, 0};
    glGetFloatv(GL_CURRENT_COLOR, c);
    glGetFloatv(GL_CURRENT_NORMAL, n);
    rgl_emit(b, RGL_OP_Color4f, "ffff", (double)c[0], (double)c[1], (double)c[2], (double)c[3]);
    rgl_emit(b, RGL_OP_Normal3f, "fff", (double)n[0], (double)n[1], (double)n[2]);
}

static void snap_materials(rgl_buf *b)
{
    static const GLenum faces[2] = {GL_FRONT, GL_BACK};
    static const GLenum colors[4] = {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION};
    for (int f = 0; f < 2; f++) {
        for (int k = 0; k < 4; k++) {
            GLfloat v[4] = {0};
            glGetMaterialfv(faces[f], colors[k], v);
            rgl_emit(b, RGL_OP_Materialfv, "eeN", faces[f], colors[k], v, 4);
        }
        GLfloat sh[4] = {0};
        glGetMaterialfv(faces[f], GL_SHININESS, sh);
        rgl_emit(b, RGL_OP_Materialf, "eef", faces[f], GL_SHININESS, (double)sh[0]);
    }
    /* Before the enables: enabling GL_COLOR_MATERIAL copies the current
     * colour into the material at once (GL 1.5, 2.14.3). */
    rgl_emit(b, RGL_OP_ColorMaterial, "ee", (uint32_t)get_i(GL_COLOR_MATERIAL_FACE),
             (uint32_t)get_i(GL_COLOR_MATERIAL_PARAMETER));
}

static void snap_enables(rgl_buf *b)
{
    for (size_t k = 0; k < sizeof caps_off / sizeof caps_off[0]; k++)
        if (glIsEnabled(caps_off[k]))
            rgl_emit(b, RGL_OP_Enable, "e", caps_off[k]);
    if (!glIsEnabled(GL_DITHER))
        rgl_emit(b, RGL_OP_Disable, "e", GL_DITHER);
}

/* User clip planes: GL keeps them in eye space, and the snapshot is
 * replayed under an identity modelview, so the eye-space equation goes in
 * as it is; with the enables. Only the planes GL has (querying past
 * GL_MAX_CLIP_PLANES would raise an error). */
static void snap_clip_planes(rgl_buf *b)
{
    GLint max = 0;
    glGetIntegerv(GL_MAX_CLIP_PLANES, &max);
    for (GLint i = 0; i < max && i < 8; i++) {
        GLenum plane = (GLenum)(GL_CLIP_PLANE0 + i);
        GLdouble eq[4] = {0, 0, 0, 0};
        glGetClipPlane(plane, eq);
        if (eq[0] != 0 || eq[1] != 0 || eq[2] != 0 || eq[3] != 0)
            rgl_emit(b, RGL_OP_ClipPlane, "edddd", plane, eq[0], eq[1], eq[2], eq[3]);
        if (glIsEnabled(plane))
            rgl_emit(b, RGL_OP_Enable, "e", plane);
    }
}

/* The stencil state, and its enable. */
static void snap_stencil(rgl_buf *b)
{
    GLint v[8] = {GL_ALWAYS, 0, -1, GL_KEEP, GL_KEEP, GL_KEEP, -1, 0};
    static const GLenum q[8] = {GL_STENCIL_FUNC, GL_STENCIL_REF, GL_STENCIL_VALUE_MASK,
                                GL_STENCIL_FAIL, GL_STENCIL_PASS_DEPTH_FAIL,
                                GL_STENCIL_PASS_DEPTH_PASS, GL_STENCIL_WRITEMASK,
                                GL_STENCIL_CLEAR_VALUE};
    for (int k = 0; k < 8; k++)
        glGetIntegerv(q[k], &v[k]);
    rgl_emit(b, RGL_OP_StencilFunc, "eie", (uint32_t)v[0], v[1], (uint32_t)v[2]);
    rgl_emit(b, RGL_OP_StencilOp, "eee", (uint32_t)v[3], (uint32_t)v[4], (uint32_t)v[5]);
    rgl_emit(b, RGL_OP_StencilMask, "e", (uint32_t)v[6]);
    rgl_emit(b, RGL_OP_ClearStencil, "i", v[7]);
    if (glIsEnabled(GL_STENCIL_TEST))
        rgl_emit(b, RGL_OP_Enable, "e", GL_STENCIL_TEST);
}

/* The pixel transfer of colours (scales, biases, GL_MAP_COLOR, where they
 * differ from GL's initial state) and every pixel map that is not GL's
 * initial one (one entry, 0): near the end of the snapshot, as the maps'
 * rows are 1.4's. glGetPixelMap writes into a bound pack buffer: set
 * aside for the reads. */
static void snap_pixel(const rgl_stream *s, rgl_buf *b)
{
    if (s->pack_buffer)
        glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    static const GLenum scale[8] = {GL_RED_SCALE, GL_GREEN_SCALE, GL_BLUE_SCALE, GL_ALPHA_SCALE,
                                    GL_RED_BIAS, GL_GREEN_BIAS, GL_BLUE_BIAS, GL_ALPHA_BIAS};
    for (int k = 0; k < 8; k++) {
        GLfloat v = k < 4 ? 1 : 0;
        glGetFloatv(scale[k], &v);
        if (v != (k < 4 ? 1 : 0))
            rgl_emit(b, RGL_OP_PixelTransferf, "ef", scale[k], (double)v);
    }
    if (get_i(GL_MAP_COLOR))
        rgl_emit(b, RGL_OP_PixelTransferi, "ei", GL_MAP_COLOR, 1);
    for (GLenum m = GL_PIXEL_MAP_I_TO_I; m <= GL_PIXEL_MAP_A_TO_A; m++) {
        GLint size = get_i(GL_PIXEL_MAP_I_TO_I_SIZE + (m - GL_PIXEL_MAP_I_TO_I));
        if (size < 1 || size > 256)
            continue;
        GLfloat v[256] = {0};
        glGetPixelMapfv(m, v);
        if (size == 1 && v[0] == 0)
            continue;
        uint8_t le[256 * 4];
        for (GLint i = 0; i < size; i++)
            rgl_put_f(le + i * 4, v[i]);
        rgl_emit(b, RGL_OP_PixelMapfv, "eiB", m, size, (const void *)le, (size_t)size * 4);
    }
    if (s->pack_buffer)
        glBindBuffer(GL_PIXEL_PACK_BUFFER, s->pack_buffer);
}

/* The back faces' stencil state (GL 2.0), only where it differs from the
 * front's: a 1.3 reader stops at these rows, so they come last and only
 * when they say something. */
static void snap_stencil_back(rgl_buf *b)
{
    if (!rgl_gl_has(2, 0, "GL_ATI_separate_stencil")) /* its queries are GL 2.0's */
        return;
    GLint f[7] = {GL_ALWAYS, 0, -1, GL_KEEP, GL_KEEP, GL_KEEP, -1};
    GLint k[7] = {GL_ALWAYS, 0, -1, GL_KEEP, GL_KEEP, GL_KEEP, -1};
    static const GLenum qf[7] = {GL_STENCIL_FUNC, GL_STENCIL_REF, GL_STENCIL_VALUE_MASK,
                                 GL_STENCIL_FAIL, GL_STENCIL_PASS_DEPTH_FAIL,
                                 GL_STENCIL_PASS_DEPTH_PASS, GL_STENCIL_WRITEMASK};
    static const GLenum qb[7] = {GL_STENCIL_BACK_FUNC, GL_STENCIL_BACK_REF,
                                 GL_STENCIL_BACK_VALUE_MASK, GL_STENCIL_BACK_FAIL,
                                 GL_STENCIL_BACK_PASS_DEPTH_FAIL, GL_STENCIL_BACK_PASS_DEPTH_PASS,
                                 GL_STENCIL_BACK_WRITEMASK};
    for (int i = 0; i < 7; i++) {
        glGetIntegerv(qf[i], &f[i]);
        glGetIntegerv(qb[i], &k[i]);
    }
    if (memcmp(f, k, sizeof f) == 0)
        return;
    rgl_emit(b, RGL_OP_StencilFuncSeparate, "eeie", GL_BACK, (uint32_t)k[0], k[1], (uint32_t)k[2]);
    rgl_emit(b, RGL_OP_StencilOpSeparate, "eeee", GL_BACK, (uint32_t)k[3], (uint32_t)k[4],
             (uint32_t)k[5]);
    rgl_emit(b, RGL_OP_StencilMaskSeparate, "ee", GL_BACK, (uint32_t)k[6]);
}

/* The draw buffer, where it is not the context's default (GL_BACK when
 * double-buffered, else GL_FRONT) and the default framebuffer is drawn
 * into: last in the snapshot, as the back faces' stencil. */
static void snap_draw_buffer(rgl_buf *b)
{
    uint32_t visual = rgl_draw_visual();
    if (!visual)
        return;
    if (rgl_gl_has(3, 0, "GL_EXT_framebuffer_object")) {
        GLint fbo = SENTINEL_I;
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &fbo);
        if (fbo != 0)
            return;
    }
    GLint db = SENTINEL_I;
    glGetIntegerv(GL_DRAW_BUFFER, &db);
    GLint def = (visual & 2) ? GL_BACK : GL_FRONT;
    if (db != SENTINEL_I && db != def)
        rgl_emit(b, RGL_OP_DrawBuffer, "ee", (uint32_t)db, visual);
}

/* The polygon stipple mask, unless it is GL's (all ones). glGetPolygonStipple
 * packs it as the pack state says and into a bound pack buffer: both are
 * set aside for the read (the program's own reads stay as they were), so
 * the bytes come in the trace's layout (bottom row first, MSB first). */
static void snap_pstipple(const rgl_stream *s, rgl_buf *b)
{
    static const GLenum pn[5] = {GL_PACK_ROW_LENGTH, GL_PACK_SKIP_ROWS, GL_PACK_SKIP_PIXELS,
                                 GL_PACK_LSB_FIRST, GL_PACK_ALIGNMENT};
    static const GLint def[5] = {0, 0, 0, GL_FALSE, 4};
    GLint v[5];
    for (int k = 0; k < 5; k++) {
        v[k] = def[k];
        glGetIntegerv(pn[k], &v[k]);
        if (v[k] != def[k])
            glPixelStorei(pn[k], def[k]);
    }
    if (s->pack_buffer)
        glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    GLubyte m[128];
    memset(m, 0xff, sizeof m);
    glGetPolygonStipple(m);
    if (s->pack_buffer)
        glBindBuffer(GL_PIXEL_PACK_BUFFER, s->pack_buffer);
    for (int k = 0; k < 5; k++)
        if (v[k] != def[k])
            glPixelStorei(pn[k], v[k]);
    bool all = true;
    for (size_t i = 0; i < sizeof m && all; i++)
        all = m[i] == 0xff;
    uint32_t id = all ? 0 : rgl_resource_put(RGL_RES_BYTES, m, sizeof m);
    if (id)
        rgl_emit(b, RGL_OP_PolygonStipple, "e", id);
}

/* Evaluators: the grids, and every map that is not GL's initial one (order
 * 1, domain [0, 1], the initial point), read back with glGetMap. GL_COEFF
 * gives glMap2's points u major, as the record packs them (Mesa; the order
 * is checked by tests/record/test_osmesa.c). */
static void snap_eval(rgl_buf *b)
{
    GLdouble g[4] = {0, 1, 0, 1};
    GLint n[2] = {1, 1};
    glGetDoublev(GL_MAP1_GRID_DOMAIN, g);
    glGetIntegerv(GL_MAP1_GRID_SEGMENTS, n);
    if (n[0] != 1 || g[0] != 0 || g[1] != 1)
        rgl_emit(b, RGL_OP_MapGrid1d, "idd", n[0], g[0], g[1]);
    glGetDoublev(GL_MAP2_GRID_DOMAIN, g);
    glGetIntegerv(GL_MAP2_GRID_SEGMENTS, n);
    if (n[0] != 1 || n[1] != 1 || g[0] != 0 || g[1] != 1 || g[2] != 0 || g[3] != 1)
        rgl_emit(b, RGL_OP_MapGrid2d, "iddidd", n[0], g[0], g[1], n[1], g[2], g[3]);

    static const double initial[9][4] = {
        {1, 1, 1, 1}, {1}, {0, 0, 1}, {0}, {0, 0}, {0, 0, 0}, {0, 0, 0, 1}, {0, 0, 0}, {0, 0, 0, 1},
    };
    for (int two = 0; two < 2; two++) {
        for (GLenum t = 0; t < 9; t++) {
            GLenum target = (two ? GL_MAP2_COLOR_4 : GL_MAP1_COLOR_4) + t;
            uint32_t k = rgl_map_components(target, NULL);
            GLint order[2] = {0, 1};
            GLdouble dom[4] = {0, 1, 0, 1};
            glGetMapiv(target, GL_ORDER, order);
            if (!two)
                order[1] = 1;
            if (order[0] < 1 || order[0] > RGL_MAX_EVAL_ORDER || order[1] < 1 ||
                order[1] > RGL_MAX_EVAL_ORDER)
                continue;
            glGetMapdv(target, GL_DOMAIN, dom);
            size_t cnt = (size_t)order[0] * (size_t)order[1] * k;
            /* Initial maps (most of them) need no allocation. */
            GLdouble small[2 * 16];
            GLdouble *pts = cnt <= 16 ? small : rgl_realloc(NULL, cnt * (sizeof *pts + 8));
            if (!pts)
                continue;
            memcpy(pts, initial[t], k * sizeof *pts);
            glGetMapdv(target, GL_COEFF, pts);
            bool initial_map = cnt == k && dom[0] == 0 && dom[1] == 1 &&
                               (!two || (dom[2] == 0 && dom[3] == 1)) &&
                               memcmp(pts, initial[t], k * sizeof *pts) == 0;
            if (!initial_map && dom[0] != dom[1] && (!two || dom[2] != dom[3])) {
                uint8_t *blob = (uint8_t *)(pts + cnt), *p = blob;
                for (size_t i = 0; i < cnt; i++)
                    p = rgl_put_d(p, pts[i]);
                if (two)
                    rgl_emit(b, RGL_OP_Map2d, "eddiiddiiB", target, dom[0], dom[1],
                             order[1] * (GLint)k, order[0], dom[2], dom[3], (GLint)k, order[1],
                             (const void *)blob, cnt * 8);
                else
                    rgl_emit(b, RGL_OP_Map1d, "eddiiB", target, dom[0], dom[1], (GLint)k,
                             order[0], (const void *)blob, cnt * 8);
            }
            if (pts != small)
                rgl_free(pts);
        }
    }
}

/* The blend colour, the separate blend functions and equations and the
 * logic op, each where the context has it (GL 1.4 and 2.0, or their
 * extensions; the blend equation with ARB_imaging too): after glBlendFunc
 * and near the end of the snapshot, as the first three are 1.4's rows. */
static void snap_blend(rgl_buf *b)
{
    if (rgl_gl_has(1, 4, "GL_EXT_blend_color") || rgl_gl_has(1, 4, "GL_ARB_imaging")) {
        GLfloat c[4] = {0, 0, 0, 0};
        glGetFloatv(GL_BLEND_COLOR, c);
        rgl_emit(b, RGL_OP_BlendColor, "ffff", (double)c[0], (double)c[1], (double)c[2],
                 (double)c[3]);
    }
    if (rgl_gl_has(1, 4, "GL_EXT_blend_func_separate"))
        rgl_emit(b, RGL_OP_BlendFuncSeparate, "eeee", (uint32_t)get_i(GL_BLEND_SRC_RGB),
                 (uint32_t)get_i(GL_BLEND_DST_RGB), (uint32_t)get_i(GL_BLEND_SRC_ALPHA),
                 (uint32_t)get_i(GL_BLEND_DST_ALPHA));
    if (rgl_gl_has(2, 0, "GL_EXT_blend_equation_separate"))
        rgl_emit(b, RGL_OP_BlendEquationSeparate, "ee", (uint32_t)get_i(GL_BLEND_EQUATION_RGB),
                 (uint32_t)get_i(GL_BLEND_EQUATION_ALPHA));
    else if (rgl_gl_has(1, 4, "GL_ARB_imaging") || rgl_gl_has(1, 4, "GL_EXT_blend_minmax"))
        rgl_emit(b, RGL_OP_BlendEquation, "e", (uint32_t)get_i(GL_BLEND_EQUATION));
    rgl_emit(b, RGL_OP_LogicOp, "e", (uint32_t)get_i(GL_LOGIC_OP_MODE));
}

static void snap_raster(rgl_buf *b)
{
    GLfloat fc[4] = {0};
    glGetFloatv(GL_FOG_COLOR, fc);
    rgl_emit(b, RGL_OP_Fogi, "ei", GL_FOG_MODE, get_i(GL_FOG_MODE));
    rgl_emit(b, RGL_OP_Fogf, "ef", GL_FOG_DENSITY, (double)get_f(GL_FOG_DENSITY));
    rgl_emit(b, RGL_OP_Fogf, "ef", GL_FOG_START, (double)get_f(GL_FOG_START));
    rgl_emit(b, RGL_OP_Fogf, "ef", GL_FOG_END, (double)get_f(GL_FOG_END));
    rgl_emit(b, RGL_OP_Fogfv, "eN", GL_FOG_COLOR, fc, 4);
    /* No core version has it: the extension string says whether to ask. */
    if (rgl_gl_has(1000, 0, "GL_NV_fog_distance"))
        rgl_emit(b, RGL_OP_Fogi, "ei", GL_FOG_DISTANCE_MODE_NV, get_i(GL_FOG_DISTANCE_MODE_NV));

    rgl_emit(b, RGL_OP_BlendFunc, "ee", (uint32_t)get_i(GL_BLEND_SRC), (uint32_t)get_i(GL_BLEND_DST));
    rgl_emit(b, RGL_OP_AlphaFunc, "ef", (uint32_t)get_i(GL_ALPHA_TEST_FUNC),
             (double)get_f(GL_ALPHA_TEST_REF));
    rgl_emit(b, RGL_OP_DepthFunc, "e", (uint32_t)get_i(GL_DEPTH_FUNC));
    GLboolean dm[4] = {GL_TRUE}, cm[4] = {GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE};
    glGetBooleanv(GL_DEPTH_WRITEMASK, dm);
    glGetBooleanv(GL_COLOR_WRITEMASK, cm);
    rgl_emit(b, RGL_OP_DepthMask, "o", (int)dm[0]);
    rgl_emit(b, RGL_OP_ColorMask, "oooo", (int)cm[0], (int)cm[1], (int)cm[2], (int)cm[3]);

    GLfloat cc[4] = {0};
    glGetFloatv(GL_COLOR_CLEAR_VALUE, cc);
    rgl_emit(b, RGL_OP_ClearColor, "ffff", (double)cc[0], (double)cc[1], (double)cc[2],
             (double)cc[3]);
    GLdouble cd[2] = {1, 0};
    glGetDoublev(GL_DEPTH_CLEAR_VALUE, cd);
    rgl_emit(b, RGL_OP_ClearDepth, "d", cd[0]);
    GLfloat ca[4] = {0};
    glGetFloatv(GL_ACCUM_CLEAR_VALUE, ca);
    rgl_emit(b, RGL_OP_ClearAccum, "ffff", (double)ca[0], (double)ca[1], (double)ca[2],
             (double)ca[3]);
    GLint sb[4] = {0, 0, 0, 0};
    glGetIntegerv(GL_SCISSOR_BOX, sb);
    if (sb[2] >= 0 && sb[3] >= 0)
        rgl_emit(b, RGL_OP_Scissor, "iiii", sb[0], sb[1], sb[2], sb[3]);
    rgl_emit(b, RGL_OP_ShadeModel, "e", (uint32_t)get_i(GL_SHADE_MODEL));
    rgl_emit(b, RGL_OP_FrontFace, "e", (uint32_t)get_i(GL_FRONT_FACE));
    rgl_emit(b, RGL_OP_CullFace, "e", (uint32_t)get_i(GL_CULL_FACE_MODE));
    GLint pm[2] = {GL_FILL, GL_FILL};
    glGetIntegerv(GL_POLYGON_MODE, pm);
    rgl_emit(b, RGL_OP_PolygonMode, "ee", GL_FRONT, (uint32_t)pm[0]);
    rgl_emit(b, RGL_OP_PolygonMode, "ee", GL_BACK, (uint32_t)pm[1]);
    rgl_emit(b, RGL_OP_PolygonOffset, "ff", (double)get_f(GL_POLYGON_OFFSET_FACTOR),
             (double)get_f(GL_POLYGON_OFFSET_UNITS));
    rgl_emit(b, RGL_OP_PointSize, "f", (double)get_f(GL_POINT_SIZE));
    /* Point parameters (GL 1.4) and sprites (GL 2.0), where the context
     * has them. */
    if (rgl_gl_has(1, 4, "GL_ARB_point_parameters")) {
        GLfloat att[3] = {1, 0, 0};
        glGetFloatv(GL_POINT_DISTANCE_ATTENUATION, att);
        rgl_emit(b, RGL_OP_PointParameterf, "ef", GL_POINT_SIZE_MIN, (double)get_f(GL_POINT_SIZE_MIN));
        rgl_emit(b, RGL_OP_PointParameterf, "ef", GL_POINT_SIZE_MAX, (double)get_f(GL_POINT_SIZE_MAX));
        rgl_emit(b, RGL_OP_PointParameterf, "ef", GL_POINT_FADE_THRESHOLD_SIZE,
                 (double)get_f(GL_POINT_FADE_THRESHOLD_SIZE));
        rgl_emit(b, RGL_OP_PointParameterfv, "eN", GL_POINT_DISTANCE_ATTENUATION, att, 3);
    }
    if (rgl_gl_has(2, 0, "GL_ARB_point_sprite")) {
        if (glIsEnabled(GL_POINT_SPRITE))
            rgl_emit(b, RGL_OP_Enable, "e", GL_POINT_SPRITE);
        if (rgl_gl_has(2, 0, "GL_VERSION_2_0")) /* core alone has the origin */
            rgl_emit(b, RGL_OP_PointParameteri, "ei", GL_POINT_SPRITE_COORD_ORIGIN,
                     get_i(GL_POINT_SPRITE_COORD_ORIGIN));
    }
    rgl_emit(b, RGL_OP_LineWidth, "f", (double)get_f(GL_LINE_WIDTH));
    GLint vp[4] = {0};
    glGetIntegerv(GL_VIEWPORT, vp);
    rgl_emit(b, RGL_OP_Viewport, "iiii", vp[0], vp[1], vp[2], vp[3]);
    GLdouble dr[2] = {0, 1};
    glGetDoublev(GL_DEPTH_RANGE, dr);
    rgl_emit(b, RGL_OP_DepthRange, "dd", dr[0], dr[1]);
}

static void snap_lists(rgl_stream *s, rgl_buf *b)
{
    for (size_t k = 0; k < s->objs.nlists; k++) {
        rgl_emit(b, RGL_OP_NewList, "eee", s->objs.lists[k].name, GL_COMPILE,
                 s->objs.lists[k].body);
        rgl_emit(b, RGL_OP_EndList, "");
    }
}

static void snap_matrices(rgl_buf *b, GLint mode)
{
    /* The texture matrices are each unit's (snaptex.c). */
    static const GLenum modes[2] = {GL_PROJECTION, GL_MODELVIEW};
    static const GLenum pnames[2] = {GL_PROJECTION_MATRIX, GL_MODELVIEW_MATRIX};
    for (int k = 0; k < 2; k++) {
        GLfloat m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        glGetFloatv(pnames[k], m);
        rgl_emit(b, RGL_OP_MatrixMode, "e", modes[k]);
        rgl_emit(b, RGL_OP_LoadMatrixf, "A", m, 16);
    }
    rgl_emit(b, RGL_OP_MatrixMode, "e", (uint32_t)mode);
}

/* GL with no current context leaves the sentinel untouched. */
static bool matrix_mode(GLint *mode)
{
    *mode = SENTINEL_I;
    glGetIntegerv(GL_MATRIX_MODE, mode);
    return *mode != SENTINEL_I;
}

bool rgl_live_context(void)
{
    GLint mode;
    return matrix_mode(&mode);
}

bool rgl_snapshot_take(rgl_stream *s, rgl_buf *out)
{
    GLint mode;
    if (!matrix_mode(&mode))
        return false;
    out->size = 0;
    rgl_emit(out, RGL_OP_MatrixMode, "e", GL_MODELVIEW);
    rgl_emit(out, RGL_OP_LoadIdentity, "");
    snap_lights_eye(out);
    snap_clip_planes(out);
    snap_stencil(out);
    snap_lights(out);
    snap_current(out);
    snap_materials(out);
    snap_enables(out);
    snap_eval(out);
    snap_raster(out);
    snap_pstipple(s, out);
    rgl_emit(out, RGL_OP_ListBase, "e", (uint32_t)get_i(GL_LIST_BASE));
    rgl_snap_textures(s, out); /* the objects, then every unit's state */
    rgl_quadrics_snapshot(out);
    snap_lists(s, out);
    snap_matrices(out, mode);
    /* 1.4's rows last: a 1.3 reader stops at the first of them. */
    snap_blend(out);
    snap_pixel(s, out);
    snap_stencil_back(out);
    snap_draw_buffer(out);
    return true;
}
