/* test_texcopy.c: texture copies, 3D textures, the texture calls Mesa
 * accepts beyond GL 1.1 (rectangle textures, mirror clamp, depth
 * textures, packed pixel types, glTexEnv's GL_POINT_SPRITE and
 * GL_TEXTURE_FILTER_CONTROL), the provoking vertex and point parameters,
 * in the interpreter, against hand-computed texels and values.
 */
#include <GL/gl.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "interp_fixture.h"
#include "interp.h"
#include "interp_internal.h"
#include "tracegen.h"

static void setup(seq *s, GLenum target, uint32_t name)
{
    CMD(s, BindTexture, target, name);
    CMD(s, TexParameteri, target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    CMD(s, TexParameteri, target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    CMD(s, Enable, target);
}

static void triangle(seq *s, float smax, float tmax)
{
    CMD(s, Begin, GL_TRIANGLES);
    CMD(s, TexCoord2f, 0, 0);
    CMD(s, Vertex2f, 0, 0);
    CMD(s, TexCoord2f, smax, 0);
    CMD(s, Vertex2f, 1, 0);
    CMD(s, TexCoord2f, 0, tmax);
    CMD(s, Vertex2f, 0, 1);
    CMD0(s, End);
}

static const scene_texture *drawn(void)
{
    if (!sc.nmeshes)
        return NULL;
    int32_t t = sc.meshes[sc.nmeshes - 1].look.texture;
    return t >= 0 && (size_t)t < sc.ntextures ? &sc.textures[t] : NULL;
}

static void check_texel(const scene_texture *t, int x, int y, int r, int g, int b, int a)
{
    CHECK(t != NULL);
    if (!t || x >= t->width || y >= t->height)
        return;
    const uint8_t *p = t->rgba + ((size_t)y * (size_t)t->width + (size_t)x) * 4;
    if (p[0] != r || p[1] != g || p[2] != b || p[3] != a) {
        fprintf(stderr, "texel (%d, %d) is %d %d %d %d, not %d %d %d %d\n", x, y, p[0], p[1],
                p[2], p[3], r, g, b, a);
        check_failures++;
    }
}

/* ---- Copies ----------------------------------------------------------------- */

static void test_copy(void)
{
    /* 2 x 2 RGBA as the recorder reads the framebuffer, bottom row first. */
    const uint8_t fb[16] = {200, 10, 20, 255, 30, 40, 50, 255, 60, 70, 80, 255, 90, 100, 110, 255};
    uint32_t id = add_bytes(fb, sizeof fb);
    const uint8_t sub[4] = {1, 2, 3, 255};
    uint32_t sid = add_bytes(sub, sizeof sub);
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    setup(&s, GL_TEXTURE_2D, 1);
    CMD(&s, CopyTexImage2D, GL_TEXTURE_2D, 0, GL_LUMINANCE, 5, 6, 2, 2, 0, id);
    triangle(&s, 1, 1);
    run(ip, &s);
    /* GL 2.1 3.8.2: luminance is the copied red. */
    check_texel(drawn(), 0, 0, 200, 200, 200, 255);
    check_texel(drawn(), 1, 1, 90, 90, 90, 255);

    seq_init(&s);
    CMD(&s, CopyTexImage2D, GL_TEXTURE_2D, 0, GL_RGB, 5, 6, 2, 2, 0, id);
    CMD(&s, CopyTexSubImage2D, GL_TEXTURE_2D, 0, 1, 0, 9, 9, 1, 1, sid);
    triangle(&s, 1, 1);
    run(ip, &s);
    check_texel(drawn(), 0, 0, 200, 10, 20, 255);
    check_texel(drawn(), 1, 0, 1, 2, 3, 255);
    check_texel(drawn(), 0, 1, 60, 70, 80, 255);
    CHECK_EQ_U(count(DIAG_GL_INVALID_VALUE) + count(DIAG_GL_INVALID_ENUM), 0);

    /* A sub-image outside the texture, a negative size, a bad target:
     * GL's errors, nothing changed. */
    seq_init(&s);
    CMD(&s, CopyTexSubImage2D, GL_TEXTURE_2D, 0, 2, 0, 0, 0, 1, 1, sid);
    CMD(&s, CopyTexImage2D, GL_TEXTURE_2D, 0, GL_RGB, 0, 0, -1, 2, 0, 0);
    CMD(&s, CopyTexImage1D, GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 2, 0, 0);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_GL_INVALID_VALUE), 2);
    CHECK_EQ_U(count(DIAG_GL_INVALID_ENUM), 1);

    /* Pixels the recorder could not read: the texture is missing, and said. */
    uint32_t before = ip->nmissing;
    seq_init(&s);
    CMD(&s, CopyTexImage2D, GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 4, 4, 0, 0);
    run(ip, &s);
    CHECK_EQ_U(ip->nmissing, before + 1);
    interp_destroy(ip);

    /* 1D: a copied row; a sub-row. */
    ip = fresh();
    seq_init(&s);
    setup(&s, GL_TEXTURE_1D, 3);
    CMD(&s, CopyTexImage1D, GL_TEXTURE_1D, 0, GL_RGBA, 0, 0, 4, 0, id);
    CMD(&s, CopyTexSubImage1D, GL_TEXTURE_1D, 0, 3, 0, 0, 1, sid);
    triangle(&s, 1, 1);
    run(ip, &s);
    check_texel(drawn(), 1, 0, 30, 40, 50, 255);
    check_texel(drawn(), 3, 0, 1, 2, 3, 255);
    interp_destroy(ip);
    free_res();
}

/* ---- 3D textures ------------------------------------------------------------ */

static void test_3d(void)
{
    /* 1 x 1 x 4 RGB: one texel per slice, red 0, 60, 120, 180. */
    const uint8_t vox[4 * 3] = {0, 1, 2, 60, 1, 2, 120, 1, 2, 180, 1, 2};
    const uint8_t sub[3] = {250, 9, 9};
    uint32_t id = add_bytes(vox, sizeof vox), sid = add_bytes(sub, sizeof sub);
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    setup(&s, GL_TEXTURE_3D, 4);
    CMD(&s, TexImage3D, GL_TEXTURE_3D, 0, GL_RGB, 1, 1, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, id);
    CMD(&s, TexParameteri, GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    CMD(&s, TexCoord3f, 0, 0, 0.6); /* nearest: slice floor(0.6 * 4) = 2 */
    CMD(&s, Rectf, 0, 0, 1, 1);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_GL_INVALID_ENUM) + count(DIAG_GL_INVALID_VALUE), 0);
    CHECK_EQ_U(count(DIAG_NOTE_TEX_3D), 1);
    CHECK_EQ_U(dlog.e[DIAG_NOTE_TEX_3D].held, 1); /* GL_NEAREST: OpenGL's own slice */
    check_texel(drawn(), 0, 0, 120, 1, 2, 255);

    /* Linear: r = 0.5 lies halfway between slices 1 and 2. */
    seq_init(&s);
    CMD(&s, TexParameteri, GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    CMD(&s, TexParameteri, GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    CMD(&s, TexCoord3f, 0, 0, 0.5);
    CMD(&s, Rectf, 0, 0, 1, 1);
    /* Clamped past the last slice; repeat wraps to the first. */
    CMD(&s, TexCoord3f, 0, 0, 7);
    CMD(&s, Rectf, 0, 0, 1, 1);
    run(ip, &s);
    CHECK(sc.nmeshes >= 2);
    if (sc.nmeshes >= 2)
        check_texel(&sc.textures[sc.meshes[sc.nmeshes - 2].look.texture], 0, 0, 90, 1, 2, 255);
    check_texel(drawn(), 0, 0, 180, 1, 2, 255);
    /* GL_LINEAR's blend, rounded to 8 bits before filtering: said. */
    CHECK_EQ_U(count(DIAG_NOTE_TEX_3D) - dlog.e[DIAG_NOTE_TEX_3D].held, 1);
    seq_init(&s);
    CMD(&s, TexParameteri, GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    CMD(&s, TexParameteri, GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_REPEAT);
    CMD(&s, TexCoord3f, 0, 0, 1.1); /* slice 4 -> 0 */
    CMD(&s, Rectf, 0, 0, 1, 1);
    /* A sub-image changes slice 3, a copied one (RGBA) slice 1. */
    CMD(&s, TexSubImage3D, GL_TEXTURE_3D, 0, 0, 0, 3, 1, 1, 1, GL_RGB, GL_UNSIGNED_BYTE, sid);
    CMD(&s, TexCoord3f, 0, 0, 0.9);
    CMD(&s, Rectf, 0, 0, 1, 1);
    run(ip, &s);
    if (sc.nmeshes >= 2)
        check_texel(&sc.textures[sc.meshes[sc.nmeshes - 2].look.texture], 0, 0, 0, 1, 2, 255);
    check_texel(drawn(), 0, 0, 250, 9, 9, 255);

    /* r varying over a primitive: untextured, and said. */
    uint64_t ignored = count(DIAG_IGNORED);
    seq_init(&s);
    CMD(&s, Begin, GL_TRIANGLES);
    CMD(&s, TexCoord3f, 0, 0, 0);
    CMD(&s, Vertex2f, 0, 0);
    CMD(&s, TexCoord3f, 0, 0, 1);
    CMD(&s, Vertex2f, 1, 0);
    CMD(&s, Vertex2f, 0, 1);
    CMD0(&s, End);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_IGNORED), ignored + 1);
    CHECK(sc.nmeshes && sc.meshes[sc.nmeshes - 1].look.texture < 0);

    seq_init(&s);
    CMD(&s, TexImage3D, GL_TEXTURE_2D, 0, GL_RGB, 2, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, id);
    CMD(&s, TexImage3D, GL_TEXTURE_3D, 0, GL_RGB, 2, -2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, id);
    CMD(&s, TexSubImage3D, GL_TEXTURE_3D, 0, 0, 0, 4, 1, 1, 1, GL_RGB, GL_UNSIGNED_BYTE, sid);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_GL_INVALID_ENUM), 1);
    CHECK_EQ_U(count(DIAG_GL_INVALID_VALUE), 2);
    interp_destroy(ip);
    free_res();
}

/* ---- Formats and types ------------------------------------------------------ */

static void test_packed(void)
{
    /* 5_6_5: red in the top 5 bits; _REV: red in the low 5. 4_4_4_4: R in
     * the top nibble. 8_8_8_8_REV with GL_BGRA: blue in the low byte.
     * 2_10_10_10_REV: the first component in the low 10 bits. */
    const uint16_t p565[2] = {0xf800, 0x07e0};
    const uint16_t p565r[2] = {0x001f, 0x0000};
    const uint16_t p4444[2] = {0xf0f8, 0x0f0f};
    const uint32_t p8888[2] = {0x80402010u, 0xff000000u};
    const uint32_t p1010[2] = {0xc00003ffu, 0x3ff00000u};
    uint32_t ids[5] = {add_bytes(p565, 4), add_bytes(p565r, 4), add_bytes(p4444, 4),
                       add_bytes(p8888, 8), add_bytes(p1010, 8)};
    const GLenum fmt[5] = {GL_RGB, GL_RGB, GL_RGBA, GL_BGRA, GL_RGBA};
    const GLenum type[5] = {GL_UNSIGNED_SHORT_5_6_5, GL_UNSIGNED_SHORT_5_6_5_REV,
                            GL_UNSIGNED_SHORT_4_4_4_4, GL_UNSIGNED_INT_8_8_8_8_REV,
                            GL_UNSIGNED_INT_2_10_10_10_REV};
    const int want[5][2][4] = {
        {{255, 0, 0, 255}, {0, 255, 0, 255}},
        {{255, 0, 0, 255}, {0, 0, 0, 255}},
        {{255, 0, 255, 136}, {0, 255, 0, 255}},
        {{64, 32, 16, 128}, {0, 0, 0, 255}},
        {{255, 0, 0, 255}, {0, 0, 255, 0}},
    };
    for (int k = 0; k < 5; k++) {
        interp *ip = fresh();
        seq s;
        seq_init(&s);
        setup(&s, GL_TEXTURE_2D, 1);
        CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 2, 1, 0, fmt[k], type[k], ids[k]);
        triangle(&s, 1, 1);
        run(ip, &s);
        for (int x = 0; x < 2; x++)
            check_texel(drawn(), x, 0, want[k][x][0], want[k][x][1], want[k][x][2],
                        want[k][x][3]);
        interp_destroy(ip);
    }
    /* A packed type of another component count than the format's. */
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    setup(&s, GL_TEXTURE_2D, 1);
    CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 2, 1, 0, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5,
        ids[0]);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_GL_INVALID_OPERATION), 1);
    interp_destroy(ip);
    free_res();
}

static void test_depth(void)
{
    const float d[2] = {0.5f, 1.0f};
    uint32_t id = add_bytes(d, sizeof d);
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    setup(&s, GL_TEXTURE_2D, 1);
    CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT16, 2, 1, 0, GL_DEPTH_COMPONENT,
        GL_FLOAT, id);
    triangle(&s, 1, 1);
    run(ip, &s);
    check_texel(drawn(), 0, 0, 128, 128, 128, 255); /* GL_LUMINANCE, the default */
    seq_init(&s);
    CMD(&s, TexParameteri, GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_ALPHA);
    triangle(&s, 1, 1);
    CMD(&s, TexParameteri, GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_INTENSITY);
    triangle(&s, 1, 1);
    run(ip, &s);
    CHECK(sc.nmeshes >= 2);
    if (sc.nmeshes >= 2) {
        const scene_texture *a = &sc.textures[sc.meshes[sc.nmeshes - 2].look.texture];
        check_texel(a, 0, 0, 255, 255, 255, 128);
    }
    check_texel(drawn(), 1, 0, 255, 255, 255, 255);
    check_texel(drawn(), 0, 0, 128, 128, 128, 128);
    /* Depth pixels for a colour format, colour pixels for a depth one. */
    seq_init(&s);
    CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_RGB, 2, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, id);
    CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 2, 1, 0, GL_LUMINANCE_ALPHA,
        GL_FLOAT, id);
    CMD(&s, TexParameteri, GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_RGB);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_GL_INVALID_OPERATION), 2);
    CHECK_EQ_U(count(DIAG_GL_INVALID_ENUM), 1);
    interp_destroy(ip);
    free_res();
}

/* ---- Targets and wraps ------------------------------------------------------ */

static void test_rect(void)
{
    uint8_t px[4 * 2 * 3];
    for (size_t i = 0; i < sizeof px; i++)
        px[i] = (uint8_t)(i * 10);
    uint32_t id = add_bytes(px, sizeof px);
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    setup(&s, GL_TEXTURE_RECTANGLE, 7);
    CMD(&s, TexImage2D, GL_TEXTURE_RECTANGLE, 0, GL_RGB, 4, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, id);
    triangle(&s, 4, 2);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_GL_INVALID_ENUM) + count(DIAG_GL_INVALID_VALUE), 0);
    const scene_texture *t = drawn();
    CHECK(t && t->width == 4 && t->height == 2 && !t->repeat_s && !t->repeat_t);
    check_texel(t, 1, 1, 150, 160, 170, 255);
    /* Coordinates in texels, divided by the size. */
    CHECK(sc.nverts >= 3);
    if (sc.nverts >= 3) {
        CHECK_NEAR(sc.verts[sc.nverts - 2].tex[0], 1, 1e-6);
        CHECK_NEAR(sc.verts[sc.nverts - 1].tex[1], 1, 1e-6);
    }
    /* GL refuses repeat, mipmaps and levels past 0 for a rectangle. */
    seq_init(&s);
    CMD(&s, TexParameteri, GL_TEXTURE_RECTANGLE, GL_TEXTURE_WRAP_S, GL_REPEAT);
    CMD(&s, TexParameteri, GL_TEXTURE_RECTANGLE, GL_TEXTURE_MIN_FILTER,
        GL_LINEAR_MIPMAP_LINEAR);
    CMD(&s, TexImage2D, GL_TEXTURE_RECTANGLE, 1, GL_RGB, 2, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, id);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_GL_INVALID_ENUM), 2);
    CHECK_EQ_U(count(DIAG_GL_INVALID_VALUE), 1);
    /* The object keeps its target: binding it to 2D is an error. */
    seq_init(&s);
    CMD(&s, BindTexture, GL_TEXTURE_2D, 7);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_GL_INVALID_OPERATION), 1);
    interp_destroy(ip);

    /* Per unit: enabled on unit 1 only, drawn from unit 1's coordinates. */
    ip = fresh();
    seq_init(&s);
    CMD(&s, ActiveTexture, GL_TEXTURE1);
    setup(&s, GL_TEXTURE_RECTANGLE, 7);
    CMD(&s, TexImage2D, GL_TEXTURE_RECTANGLE, 0, GL_RGB, 4, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, id);
    CMD(&s, ActiveTexture, GL_TEXTURE0);
    CMD(&s, Begin, GL_TRIANGLES);
    CMD(&s, MultiTexCoord2f, GL_TEXTURE1, 2, 1);
    CMD(&s, Vertex2f, 0, 0);
    CMD(&s, Vertex2f, 1, 0);
    CMD(&s, Vertex2f, 0, 1);
    CMD0(&s, End);
    run(ip, &s);
    CHECK(interp_texture_rect_on(ip, 1) && !interp_texture_rect_on(ip, 0));
    t = drawn();
    CHECK(t && t->width == 4 && t->height == 2);
    if (sc.nverts >= 1) {
        CHECK_NEAR(sc.verts[sc.nverts - 1].tex[0], 0.5, 1e-6);
        CHECK_NEAR(sc.verts[sc.nverts - 1].tex[1], 0.5, 1e-6);
    }
    interp_destroy(ip);
    free_res();
}

static void test_mirror_clamp(void)
{
    const uint8_t px[2 * 4] = {10, 20, 30, 255, 40, 50, 60, 255};
    uint32_t id = add_bytes(px, sizeof px);
    const GLenum modes[3] = {GL_MIRROR_CLAMP_EXT, GL_MIRROR_CLAMP_TO_EDGE_EXT,
                             GL_MIRROR_CLAMP_TO_BORDER_EXT};
    for (int k = 0; k < 3; k++) {
        interp *ip = fresh();
        seq s;
        seq_init(&s);
        setup(&s, GL_TEXTURE_2D, 1);
        CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, id);
        CMD(&s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, modes[k]);
        CMD(&s, Begin, GL_TRIANGLES);
        CMD(&s, TexCoord2f, -1, 0);
        CMD(&s, Vertex2f, 0, 0);
        CMD(&s, TexCoord2f, 0.5, 0);
        CMD(&s, Vertex2f, 1, 0);
        CMD(&s, TexCoord2f, 1, 1);
        CMD(&s, Vertex2f, 0, 1);
        CMD0(&s, End);
        run(ip, &s);
        CHECK_EQ_U(count(DIAG_GL_INVALID_ENUM), 0);
        CHECK_EQ_U(count(DIAG_NOTE_TEX_MIRROR_CLAMP), 1);
        /* GL_NEAREST: each mode as OpenGL samples it. */
        CHECK_EQ_U(dlog.e[DIAG_NOTE_TEX_MIRROR_CLAMP].held, 1);
        /* The image mirrored once beside itself: [-1, 1] onto [0, 1]. */
        const scene_texture *t = drawn();
        CHECK(t && t->width == 4 && !t->repeat_s && t->border_s == (k == 2));
        check_texel(t, 0, 0, 40, 50, 60, 255);
        check_texel(t, 1, 0, 10, 20, 30, 255);
        check_texel(t, 2, 0, 10, 20, 30, 255);
        check_texel(t, 3, 0, 40, 50, 60, 255);
        if (sc.nverts >= 3) {
            CHECK_NEAR(sc.verts[sc.nverts - 3].tex[0], 0, 1e-6);
            CHECK_NEAR(sc.verts[sc.nverts - 2].tex[0], 0.75, 1e-6);
            CHECK_NEAR(sc.verts[sc.nverts - 1].tex[1], 1, 1e-6); /* t repeats: unchanged */
        }
        interp_destroy(ip);
    }
    /* GL_MIRROR_CLAMP_EXT under linear filtering blends the border in at
     * the edge, where the image drawn is clamped to its edge texels. */
    for (int lin = 0; lin < 2; lin++) {
        interp *ip = fresh();
        seq s;
        seq_init(&s);
        setup(&s, GL_TEXTURE_2D, 1);
        CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, id);
        CMD(&s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_MIRROR_CLAMP_EXT);
        CMD(&s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, lin ? GL_LINEAR : GL_NEAREST);
        triangle(&s, 1, 1);
        run(ip, &s);
        CHECK_EQ_U(count(DIAG_NOTE_TEX_MIRROR_CLAMP), 1);
        CHECK_EQ_U(dlog.e[DIAG_NOTE_TEX_MIRROR_CLAMP].held, lin ? 0 : 1);
        interp_destroy(ip);
    }
    free_res();
}

static void test_texenv_targets(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, TexEnvi, GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
    CMD(&s, TexEnvf, GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 0.5);
    CMD(&s, TexParameterf, GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 0);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_GL_INVALID_ENUM), 0);
    /* kept for the draws that use them (test_sprites.c, tex_lod_bias) */
    CHECK(ip->st.a.texture.coord_replace && ip->st.a.texture.lod_bias == 0.5f);
    seq_init(&s);
    CMD(&s, TexEnvi, GL_POINT_SPRITE, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    CMD(&s, TexEnvi, GL_TEXTURE_FILTER_CONTROL, GL_COORD_REPLACE, 1);
    CMD(&s, TexEnvi, GL_POINT_SPRITE, GL_COORD_REPLACE, 7);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_GL_INVALID_ENUM), 3);
    interp_destroy(ip);
}

/* ---- Provoking vertex and point parameters --------------------------------------- */

static void test_provoking(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, ShadeModel, GL_FLAT);
    CMD(&s, ProvokingVertex, GL_FIRST_VERTEX_CONVENTION);
    CMD(&s, Begin, GL_TRIANGLE_FAN);
    for (int i = 0; i < 4; i++)
        CMD(&s, Vertex2f, i == 0 ? 0 : 1, i);
    CMD0(&s, End);
    CMD(&s, Begin, GL_TRIANGLES);
    for (int i = 0; i < 3; i++)
        CMD(&s, Vertex2f, i, i == 1);
    CMD0(&s, End);
    run(ip, &s);
    /* A fan's triangle i provokes with vertex i + 1, a triangle with its first. */
    CHECK_EQ_U(sc.ntris, 3);
    if (sc.ntris == 3) {
        CHECK_EQ_U(sc.tris[0].provoking, 1);
        CHECK_EQ_U(sc.tris[1].provoking, 2);
        CHECK_EQ_U(sc.tris[2].provoking, 4);
    }
    seq_init(&s);
    CMD(&s, ProvokingVertex, GL_FLAT);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_GL_INVALID_ENUM), 1);
    CHECK_EQ_U(ip->st.a.lighting.provoking, GL_FIRST_VERTEX_CONVENTION);
    seq_init(&s);
    CMD(&s, ProvokingVertexEXT, GL_LAST_VERTEX_CONVENTION);
    CMD(&s, PointParameterfvARB, GL_POINT_DISTANCE_ATTENUATION, 1, 2, 3);
    CMD(&s, PointParameterfEXT, GL_POINT_SIZE_MIN, 4);
    run(ip, &s);
    CHECK_EQ_U(ip->st.a.lighting.provoking, GL_LAST_VERTEX_CONVENTION);
    CHECK_NEAR(ip->st.a.point.atten[2], 3, 0);
    CHECK_NEAR(ip->st.a.point.size_min, 4, 0);
    interp_destroy(ip);
}

static void test_point_parameters(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, PointSize, 20);
    CMD(&s, PointParameterfv, GL_POINT_DISTANCE_ATTENUATION, 1, 0, 0.25);
    CMD(&s, PointParameteri, GL_POINT_SIZE_MAX, 8);
    CMD(&s, PointParameterf, GL_POINT_SIZE_MIN, 2);
    run(ip, &s);
    const gl_attribs *a = &ip->st.a;
    CHECK(interp_point_params_set(a));
    double fade, eye[3] = {3, 4, -2};
    /* 20 / sqrt(1 + 0.25 * 2^2) = 14.14, clamped to 8; at z = -10: 20 / sqrt(26) = 3.92. */
    CHECK_NEAR(interp_point_size(a, eye, &fade), 8, 1e-9);
    eye[2] = -10;
    CHECK_NEAR(interp_point_size(a, eye, &fade), 20 / sqrt(26.0), 1e-6);
    eye[2] = -1000;
    CHECK_NEAR(interp_point_size(a, eye, &fade), 2, 1e-9);
    seq_init(&s);
    CMD(&s, PointParameterf, GL_POINT_SIZE_MIN, -1);
    CMD(&s, PointParameterf, GL_POINT_DISTANCE_ATTENUATION, 1);
    CMD(&s, PointParameteri, GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
    CMD(&s, PointParameteri, GL_POINT_SPRITE_COORD_ORIGIN, GL_LEFT);
    CMD(&s, MatrixMode, GL_PROJECTION);
    CMD(&s, Ortho, -20, 20, -20, 20, -100, 100);
    CMD(&s, MatrixMode, GL_MODELVIEW);
    CMD(&s, Begin, GL_POINTS);
    CMD(&s, Vertex3f, 0, 0, -10); /* 3.92 pixels: above the default threshold of 1 */
    CMD0(&s, End);
    CMD(&s, PointParameterf, GL_POINT_FADE_THRESHOLD_SIZE, 4);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_GL_INVALID_VALUE), 1);
    CHECK_EQ_U(count(DIAG_GL_INVALID_ENUM), 2);
    CHECK_EQ_U(count(DIAG_NOTE_POINT_FADE), 0); /* set, nothing drawn under it yet */
    seq_init(&s);
    CMD(&s, Begin, GL_POINTS);
    CMD(&s, Vertex3f, 0, 0, -10); /* now below it */
    CMD0(&s, End);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_NOTE_POINT_FADE), 1);
    CHECK_NEAR(a->point.size_min, 2, 0);
    interp_destroy(ip);
}

/* ---- With issue 14's levels and cube maps ----------------------------------- */

/* Where these targets meet the levels and cube maps: GL's target priority
 * (GL 2.1 3.8.15 with ARB_texture_rectangle: cube map, 3D, rectangle, 2D,
 * 1D), a rectangle's single level, copies into a level and into cube-map
 * faces, a depth texture's levels. */
static void test_with_levels(void)
{
    const uint8_t fb[16] = {200, 10, 20, 255, 30, 40, 50, 255, 60, 70, 80, 255, 90, 100, 110, 255};
    uint32_t id = add_bytes(fb, sizeof fb);
    const uint8_t one[4] = {9, 8, 7, 255};
    uint32_t id1 = add_bytes(one, sizeof one);
    uint8_t px[4 * 2 * 3];
    for (size_t i = 0; i < sizeof px; i++)
        px[i] = (uint8_t)(i * 10);
    uint32_t idr = add_bytes(px, sizeof px);
    const float d[2] = {0.5f, 1.0f};
    uint32_t idd = add_bytes(d, sizeof d), idd1 = add_bytes(d, sizeof d[0]);
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    setup(&s, GL_TEXTURE_2D, 1);
    CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, id);
    setup(&s, GL_TEXTURE_RECTANGLE, 2);
    CMD(&s, TexImage2D, GL_TEXTURE_RECTANGLE, 0, GL_RGB, 4, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, idr);
    triangle(&s, 1, 1);
    run(ip, &s);
    const scene_texture *t = drawn();
    CHECK(t && t->width == 4 && t->height == 2); /* the rectangle over 2D */

    /* The cube map over the rectangle: incomplete, the unit draws
     * untextured; its faces copied, it draws. */
    seq_init(&s);
    CMD(&s, BindTexture, GL_TEXTURE_CUBE_MAP, 3);
    CMD(&s, Enable, GL_TEXTURE_CUBE_MAP);
    triangle(&s, 1, 1);
    run(ip, &s);
    CHECK(sc.nmeshes > 0 && sc.meshes[sc.nmeshes - 1].look.texture < 0);
    seq_init(&s);
    for (GLenum f = GL_TEXTURE_CUBE_MAP_POSITIVE_X; f <= GL_TEXTURE_CUBE_MAP_NEGATIVE_Z; f++)
        CMD(&s, CopyTexImage2D, f, 0, GL_RGB, 0, 0, 1, 1, 0, id1);
    triangle(&s, 1, 1);
    run(ip, &s);
    t = drawn();
    CHECK(t && t->cube);
    check_texel(t, 0, 0, 9, 8, 7, 255);

    /* A rectangle's base level stays 0. */
    seq_init(&s);
    CMD(&s, Disable, GL_TEXTURE_CUBE_MAP);
    CMD(&s, TexParameteri, GL_TEXTURE_RECTANGLE, GL_TEXTURE_BASE_LEVEL, 1);
    CMD(&s, Disable, GL_TEXTURE_RECTANGLE);
    /* A copy into level 1 completes the 2D texture's chain. */
    CMD(&s, CopyTexImage2D, GL_TEXTURE_2D, 1, GL_RGB, 0, 0, 1, 1, 0, id1);
    CMD(&s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    triangle(&s, 1, 1);
    run(ip, &s);
    t = drawn();
    CHECK(t && t->width == 2 && t->mip_next >= 0 && (size_t)t->mip_next < sc.ntextures);
    if (t && t->mip_next >= 0 && (size_t)t->mip_next < sc.ntextures)
        check_texel(&sc.textures[t->mip_next], 0, 0, 9, 8, 7, 255);

    /* A depth texture's levels all follow GL_DEPTH_TEXTURE_MODE; a cube
     * map's face is never a depth image (GL 2.1 3.8.1). */
    seq_init(&s);
    CMD(&s, BindTexture, GL_TEXTURE_2D, 4);
    CMD(&s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 2, 1, 0, GL_DEPTH_COMPONENT,
        GL_FLOAT, idd);
    CMD(&s, TexImage2D, GL_TEXTURE_2D, 1, GL_DEPTH_COMPONENT, 1, 1, 0, GL_DEPTH_COMPONENT,
        GL_FLOAT, idd1);
    CMD(&s, TexParameteri, GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_ALPHA);
    triangle(&s, 1, 1);
    CMD(&s, TexImage2D, GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_DEPTH_COMPONENT, 1, 1, 0,
        GL_DEPTH_COMPONENT, GL_FLOAT, idd1);
    run(ip, &s);
    t = drawn();
    CHECK(t && t->mip_next >= 0 && (size_t)t->mip_next < sc.ntextures);
    check_texel(t, 1, 0, 255, 255, 255, 255);
    if (t && t->mip_next >= 0 && (size_t)t->mip_next < sc.ntextures)
        check_texel(&sc.textures[t->mip_next], 0, 0, 255, 255, 255, 128);
    CHECK_EQ_U(count(DIAG_GL_INVALID_VALUE), 1);
    CHECK_EQ_U(count(DIAG_GL_INVALID_OPERATION), 1);
    CHECK_EQ_U(count(DIAG_GL_INVALID_ENUM), 0);
    interp_destroy(ip);
    free_res();
}

int main(void)
{
    scene_init(&sc);
    fx_fetch = fetch_res;
    test_copy();
    test_3d();
    test_packed();
    test_depth();
    test_rect();
    test_mirror_clamp();
    test_texenv_targets();
    test_provoking();
    test_point_parameters();
    test_with_levels();
    scene_finish(&sc);
    return CHECK_RESULT("test_texcopy");
}
