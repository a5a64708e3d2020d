/* test_tex_env.c: issue 14's texture items in the interpreter and the
 * writer: GL_MIRRORED_REPEAT as a mirrored image, GL_MODULATE of a
 * coloured lit material as a tinted image with per-channel finish terms,
 * a lone unit's GL_BLEND and GL_ADD as a per-channel pigment, and the
 * alpha test (faces whose every vertex fails dropped, texels that fail
 * made transparent), texture levels (base and max level, generated
 * mipmaps, completeness) and mipmap runs in the writer.
 */
#include <GL/gl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "interp_fixture.h"
#include "interp.h"
#include "outbuf.h"
#include "povwrite.h"
#include "povwrite_mipmap.h"
#include "povwrite_texture.h"
#include "tracegen.h"

/* A 2 x 1 RGBA texture (red, green; alpha 255, 100) bound as name 1,
 * nearest, with env mode env, enabled. */
static void texture(seq *s, uint32_t id, GLenum env, GLenum wrap)
{
    CMD(s, BindTexture, GL_TEXTURE_2D, 1);
    CMD(s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    CMD(s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    CMD(s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap);
    CMD(s, TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, id);
    CMD(s, TexEnvi, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, env);
    CMD(s, Enable, GL_TEXTURE_2D);
}

static void triangle(seq *s)
{
    CMD(s, Begin, GL_TRIANGLES);
    CMD(s, TexCoord2f, 0, 0);
    CMD(s, Vertex2f, 0, 0);
    CMD(s, TexCoord2f, 2, 0);
    CMD(s, Vertex2f, 1, 0);
    CMD(s, TexCoord2f, 0, 1);
    CMD(s, Vertex2f, 0, 1);
    CMD0(s, End);
}

static const uint8_t px[8] = {255, 0, 0, 255, 0, 255, 0, 100};

static void test_mirrored(void)
{
    uint32_t id = add_bytes(px, sizeof px);
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    texture(&s, id, GL_REPLACE, GL_MIRRORED_REPEAT);
    triangle(&s);
    run(ip, &s);
    CHECK_EQ_U(sc.ntextures, 1);
    CHECK_EQ_U(count(DIAG_NOTE_TEX_SAMPLING), 0); /* no longer drawn as repeat */
    if (sc.ntextures == 1) {
        CHECK(sc.textures[0].mirror_s && !sc.textures[0].mirror_t);
        povtex pt;
        memset(&pt, 0, sizeof pt);
        float lo[2] = {0, 0}, hi[2] = {2, 1}, scale[2], off[2];
        CHECK(povtex_map(&pt, &sc, 0, lo, hi, false, NULL, scale, off) == 0);
        if (pt.n == 1) {
            /* red green | green red: the texture and its mirror image */
            const povtex_image *im = &pt.imgs[0];
            CHECK(im->width == 4 && im->height == 1);
            CHECK(im->rgba[0] == 255 && im->rgba[4 + 1] == 255 && im->rgba[8 + 1] == 255 &&
                  im->rgba[12] == 255);
            CHECK_NEAR(scale[0], 0.5, 0);
            CHECK_NEAR(off[0], 0, 0);
        }
        /* a tint multiplies the colour, rounded */
        float tint[3] = {1, 0.5f, 0.25f};
        CHECK(povtex_map(&pt, &sc, 0, lo, hi, false, tint, scale, off) == 1);
        if (pt.n == 2) {
            CHECK(pt.imgs[1].rgba[0] == 255 && pt.imgs[1].rgba[5] == 128);
            CHECK(strcmp(pt.imgs[0].name, pt.imgs[1].name) != 0);
        }
        povtex_finish(&pt);
    }
    interp_destroy(ip);
    free_res();
}

/* Lit MODULATE: a gold material's diffuse goes into the image; the
 * finish's diffuse is its largest channel. A grey one keeps the mean. */
static void test_modulate_tint(void)
{
    uint32_t id = add_bytes(px, sizeof px);
    for (int gold = 0; gold < 2; gold++) {
        interp *ip = fresh();
        seq s;
        seq_init(&s);
        CMD(&s, Viewport, 0, 0, 100, 100);
        CMD(&s, Enable, GL_LIGHTING);
        CMD(&s, Enable, GL_LIGHT0);
        if (gold)
            CMD(&s, Materialfv, GL_FRONT, GL_DIFFUSE, 0.8, 0.6, 0.2, 1);
        else
            CMD(&s, Materialfv, GL_FRONT, GL_DIFFUSE, 0.5, 0.5, 0.5, 1);
        texture(&s, id, GL_MODULATE, GL_REPEAT);
        CMD(&s, Normal3f, 0, 0, 1);
        triangle(&s);
        run(ip, &s);
        interp_end_frame(ip);
        povwriter *w = povwriter_create();
        write_sdl_with(w, NULL);
        if (gold) {
            CHECK(strstr(sdl, "finish{diffuse 0.8 ") != NULL);
            CHECK(povwriter_image(w, 0) != NULL);
            const povtex_image *im = povwriter_image(w, 0);
            /* red texel times (1, 0.75, 0.25): red stays, green texel times 0.75 */
            if (im)
                CHECK(im->rgba[0] == 255 && im->rgba[5] == 191 && im->tint[2] == 64);
        } else {
            CHECK(strstr(sdl, "finish{diffuse 0.5 ") != NULL);
        }
        CHECK(strstr(sdl, "nan") == NULL && strstr(sdl, "inf") == NULL);
        povwriter_destroy(w);
        interp_destroy(ip);
    }
    /* GL_COLOR_MATERIAL colours that vary: a tinted function per entry, no note. */
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Viewport, 0, 0, 100, 100);
    CMD(&s, Enable, GL_LIGHTING);
    CMD(&s, Enable, GL_LIGHT0);
    CMD(&s, Enable, GL_COLOR_MATERIAL);
    texture(&s, id, GL_MODULATE, GL_REPEAT);
    CMD(&s, Normal3f, 0, 0, 1);
    CMD(&s, Begin, GL_TRIANGLES);
    /* Lit below white (0.8 x (1 + 0.2 ambient) < 1): past it, GL's clamped
     * per-vertex colours are drawn instead (interp_relit.c). */
    CMD(&s, Color3f, 0.8, 0.4, 0);
    CMD(&s, Vertex2f, 0, 0);
    CMD(&s, Color3f, 0, 0.4, 0.8);
    CMD(&s, Vertex2f, 1, 0);
    CMD(&s, Vertex2f, 0, 1);
    CMD0(&s, End);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_NOTE_TEX_MODULATE_CM), 0);
    interp_end_frame(ip);
    povwriter *w = povwriter_create();
    write_sdl_with(w, NULL);
    CHECK(strstr(sdl, "#declare rgl_mt0a=function{pigment{image_map{") != NULL);
    CHECK(strstr(sdl, "rgl_mt0a(x,y,z).red*(1)") != NULL);  /* (1, 0.5, 0): red the largest */
    CHECK(strstr(sdl, "rgl_mt0a(x,y,z).blue*(1)") != NULL); /* (0, 0.5, 1) */
    povwriter_destroy(w);
    interp_destroy(ip);
    free_res();
}

/* A lone unit's BLEND and ADD, unlit: a pigment function of the image and
 * the environment per channel; lit: the lit surface times one pigment
 * averaged with the added one (povlight_texture_env). */
static void test_blend_add(void)
{
    uint32_t id = add_bytes(px, sizeof px);
    static const GLenum modes[2] = {GL_BLEND, GL_ADD};
    static const uint32_t scene_modes[2] = {SCENE_ENV_BLEND, SCENE_ENV_ADD};
    for (int m = 0; m < 2; m++)
        for (int lit = 0; lit < 2; lit++) {
            interp *ip = fresh();
            seq s;
            seq_init(&s);
            CMD(&s, Viewport, 0, 0, 100, 100);
            if (lit) {
                CMD(&s, Enable, GL_LIGHTING);
                CMD(&s, Enable, GL_LIGHT0);
            }
            CMD(&s, TexEnvfv, GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, 0.25, 0.5, 1, 1);
            texture(&s, id, modes[m], GL_REPEAT);
            CMD(&s, Color3f, 0.5, 0.5, 0.5);
            triangle(&s);
            run(ip, &s);
            CHECK_EQ_U(sc.ntextures, 1);
            if (sc.ntextures)
                CHECK_EQ_U(sc.textures[0].env_mode, scene_modes[m]);
            CHECK_EQ_U(count(DIAG_NOTE_TEXTURE), 0);
            interp_end_frame(ip);
            povwriter *w = povwriter_create();
            write_sdl_with(w, NULL);
            if (!lit) {
                CHECK_EQ_U(strstr(sdl, "#declare rgl_mt0a=function{pigment{image_map{") != NULL, 1);
                CHECK(strstr(sdl, "uv_mapping average pigment_map{") != NULL);
                if (m == 0) /* Cf (1 - Ct) + Cc Ct, Cc blue 1 */
                    CHECK(strstr(sdl, "((0.5)*(1-rgl_mt0a(x,y,z).blue)+(1)*rgl_mt0a(x,y,z).blue)") != NULL);
                else
                    CHECK(strstr(sdl, "min(1,(0.5)+rgl_mt0a(x,y,z).red)") != NULL);
            } else { /* the lit colour and the added term, averaged at twice their weight */
                CHECK(strstr(sdl, "texture{average texture_map{[1 pigment{") != NULL);
                CHECK(strstr(sdl, "finish{emission 2 diffuse 0 ambient 0}]}}") != NULL);
                if (m == 0)
                    CHECK(strstr(sdl, "(1-rgl_mt0a(x,y,z).red)*(1)") != NULL);
            }
            povwriter_destroy(w);
            interp_destroy(ip);
        }
    free_res();
}

/* The alpha test: untextured faces whose every vertex fails are dropped,
 * faces across the reference kept with a note; a texture's failing texels
 * become transparent in its image (alpha 100 fails GL_GREATER 0.5). */
static void test_alpha_test(void)
{
    uint32_t id = add_bytes(px, sizeof px);
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Viewport, 0, 0, 100, 100);
    CMD(&s, AlphaFunc, GL_GREATER, 0.5);
    CMD(&s, Enable, GL_ALPHA_TEST);
    CMD(&s, Color4f, 1, 0, 0, 0.3);
    triangle(&s); /* dropped */
    CMD(&s, Color4f, 1, 0, 0, 0.8);
    triangle(&s); /* kept */
    run(ip, &s);
    CHECK_EQ_U(sc.ntris, 1);
    CHECK_EQ_U(count(DIAG_NOTE_ALPHA_TEST), 0);
    seq_init(&s);
    CMD(&s, Begin, GL_TRIANGLES); /* across the reference: kept, noted */
    CMD(&s, Color4f, 1, 0, 0, 0.2);
    CMD(&s, Vertex2f, 0, 0);
    CMD(&s, Color4f, 1, 0, 0, 0.9);
    CMD(&s, Vertex2f, 1, 0);
    CMD(&s, Vertex2f, 0, 1);
    CMD0(&s, End);
    run(ip, &s);
    CHECK_EQ_U(sc.ntris, 2);
    CHECK_EQ_U(count(DIAG_NOTE_ALPHA_TEST), 1);
    interp_destroy(ip);

    ip = fresh();
    seq_init(&s);
    CMD(&s, Viewport, 0, 0, 100, 100);
    CMD(&s, AlphaFunc, GL_GREATER, 0.5);
    CMD(&s, Enable, GL_ALPHA_TEST);
    texture(&s, id, GL_MODULATE, GL_REPEAT);
    triangle(&s);
    run(ip, &s);
    CHECK_EQ_U(sc.ntextures, 1);
    if (sc.ntextures) {
        CHECK_EQ_U(sc.textures[0].alpha_func, SCENE_CMP_GREATER);
        CHECK(sc.textures[0].alpha_uses_af);
        povtex pt;
        memset(&pt, 0, sizeof pt);
        float lo[2] = {0, 0}, hi[2] = {1, 1}, scale[2], off[2];
        CHECK(povtex_map(&pt, &sc, 0, lo, hi, false, NULL, scale, off) == 0);
        if (pt.n == 1) {
            CHECK(pt.imgs[0].alpha);
            CHECK(pt.imgs[0].rgba[3] == 255 && pt.imgs[0].rgba[7] == 0);
        }
        povtex_finish(&pt);
    }
    CHECK_EQ_U(count(DIAG_NOTE_ALPHA_TEST), 0);
    interp_destroy(ip);

    /* GL_LINEAR: the test on the filtered alpha, a pigment_map by transmit
     * (pass below 1 - 0.5), the alpha image unthresholded. */
    ip = fresh();
    seq_init(&s);
    CMD(&s, Viewport, 0, 0, 100, 100);
    CMD(&s, AlphaFunc, GL_GREATER, 0.5);
    CMD(&s, Enable, GL_ALPHA_TEST);
    texture(&s, id, GL_MODULATE, GL_REPEAT);
    CMD(&s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    triangle(&s);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_NOTE_ALPHA_TEST), 0);
    interp_end_frame(ip);
    povwriter *w = povwriter_create();
    write_sdl_with(w, NULL);
    CHECK(strstr(sdl, "#declare rgl_at0=function{pigment{image_map{") != NULL);
    CHECK(strstr(sdl, "uv_mapping function{rgl_at0(x,y,z).transmit}pigment_map{[0 image_map{") != NULL);
    CHECK(strstr(sdl, "[0.5 rgbt<1,1,1,1>][1 rgbt<1,1,1,1>]}") != NULL);
    povwriter_destroy(w);
    interp_destroy(ip);
    free_res();
}

/* Levels: GL_TEXTURE_BASE_LEVEL picks the image (white level 0, grey
 * level 1), GL_TEXTURE_MAX_LEVEL ends the chain a mipmapping filter
 * needs, GL_GENERATE_MIPMAP makes the levels (2 x 2 means), the chain is
 * linked level by level in the scene, and a copy of the state shares the
 * levels until glTexSubImage2D changes one. */
static void test_levels(void)
{
    uint8_t white[4 * 4 * 3], grey[2 * 2 * 3], one[3] = {10, 20, 30};
    memset(white, 255, sizeof white);
    memset(grey, 128, sizeof grey);
    uint32_t iw = add_bytes(white, sizeof white), ig = add_bytes(grey, sizeof grey);
    uint32_t i1 = add_bytes(one, sizeof one);
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, BindTexture, GL_TEXTURE_2D, 1);
    CMD(&s, Enable, GL_TEXTURE_2D);
    CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, iw);
    CMD(&s, TexImage2D, GL_TEXTURE_2D, 1, GL_RGB, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, ig);
    CMD(&s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1);
    CMD(&s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    triangle(&s);
    run(ip, &s);
    CHECK_EQ_U(sc.ntextures, 1);
    if (sc.ntextures == 1)
        CHECK(sc.textures[0].width == 2 && sc.textures[0].rgba[0] == 128);
    /* Mipmapped from level 1: level 2 (1 x 1) missing, incomplete. */
    seq_init(&s);
    CMD(&s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    triangle(&s);
    run(ip, &s);
    CHECK_EQ_U(sc.nmeshes, 2);
    if (sc.nmeshes == 2)
        CHECK(sc.meshes[1].look.texture == -1);
    /* GL_TEXTURE_MAX_LEVEL 1: the chain is level 1 alone, complete. */
    seq_init(&s);
    CMD(&s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 1);
    triangle(&s);
    run(ip, &s);
    if (sc.nmeshes == 3) {
        int32_t t = sc.meshes[2].look.texture;
        CHECK(t >= 0 && sc.textures[t].mip_filter == SCENE_MIP_LINEAR_MIPMAP_LINEAR &&
              sc.textures[t].mip_next == -1 && sc.textures[t].width == 2);
    }
    /* A wrong size at level 2 keeps it incomplete; the right one completes. */
    seq_init(&s);
    CMD(&s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 1000);
    CMD(&s, TexImage2D, GL_TEXTURE_2D, 2, GL_RGB, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, ig);
    triangle(&s);
    CMD(&s, TexImage2D, GL_TEXTURE_2D, 2, GL_RGB, 1, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, i1);
    triangle(&s);
    run(ip, &s);
    CHECK_EQ_U(sc.nmeshes, 5);
    if (sc.nmeshes == 5) {
        CHECK(sc.meshes[3].look.texture == -1);
        int32_t t = sc.meshes[4].look.texture;
        CHECK(t >= 0 && sc.textures[t].mip_next >= 0);
        if (t >= 0 && sc.textures[t].mip_next >= 0) {
            const scene_texture *l2 = &sc.textures[sc.textures[t].mip_next];
            CHECK(l2->width == 1 && l2->rgba[0] == 10 && l2->rgba[2] == 30 && l2->mip_next == -1);
        }
    }
    /* Hostile values: a negative level, level 15, a negative base level. */
    seq_init(&s);
    CMD(&s, TexImage2D, GL_TEXTURE_2D, 15, GL_RGB, 1, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, i1);
    CMD(&s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, -1);
    CMD(&s, TexParameterf, GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1e30);
    triangle(&s);
    run(ip, &s);
    CHECK(count(DIAG_GL_INVALID_VALUE) >= 2);
    if (sc.nmeshes == 6)
        CHECK(sc.meshes[5].look.texture == -1); /* base level past the levels */
    interp_destroy(ip);

    /* GL_GENERATE_MIPMAP: levels from the base, each the mean of 2 x 2. */
    uint8_t px4[2 * 2 * 3] = {0, 0, 0, 100, 100, 100, 200, 200, 200, 255, 255, 255};
    uint32_t i4 = add_bytes(px4, sizeof px4);
    ip = fresh();
    seq_init(&s);
    CMD(&s, BindTexture, GL_TEXTURE_2D, 3);
    CMD(&s, Enable, GL_TEXTURE_2D);
    CMD(&s, TexParameteri, GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    CMD(&s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_RGB, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, i4);
    triangle(&s);
    run(ip, &s);
    CHECK_EQ_U(sc.ntextures, 2);
    if (sc.ntextures == 2 && sc.nmeshes == 1) {
        int32_t t = sc.meshes[0].look.texture;
        CHECK(t == 1 && sc.textures[1].mip_next == 0);
        CHECK_EQ_U(sc.textures[0].rgba[0], 139); /* (0 + 100 + 200 + 255 + 2) / 4 */
    }
    interp_destroy(ip);
    free_res();
}

/* Mipmap runs: a quad on one plane is one run with lambda per pixel; the
 * SDL declares its functions and a pigment_map over the levels. */
static void test_mip_runs(void)
{
    uint8_t px16[16 * 16 * 3];
    for (size_t i = 0; i < sizeof px16; i++)
        px16[i] = (uint8_t)(i * 13);
    uint32_t id = add_bytes(px16, sizeof px16);
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Viewport, 0, 0, 200, 100);
    CMD(&s, MatrixMode, GL_PROJECTION);
    CMD(&s, Frustum, -1, 1, -0.5, 0.5, 1, 100);
    CMD(&s, MatrixMode, GL_MODELVIEW);
    CMD(&s, BindTexture, GL_TEXTURE_2D, 1);
    CMD(&s, Enable, GL_TEXTURE_2D);
    CMD(&s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    CMD(&s, Build2DMipmaps, GL_TEXTURE_2D, GL_RGB, 16, 16, GL_RGB, GL_UNSIGNED_BYTE, id);
    CMD(&s, TexEnvi, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    CMD(&s, Begin, GL_QUADS); /* a floor going away */
    CMD(&s, TexCoord2f, 0, 0);
    CMD(&s, Vertex3f, -5, -1, -2);
    CMD(&s, TexCoord2f, 8, 0);
    CMD(&s, Vertex3f, 5, -1, -2);
    CMD(&s, TexCoord2f, 8, 8);
    CMD(&s, Vertex3f, 5, -1, -50);
    CMD(&s, TexCoord2f, 0, 8);
    CMD(&s, Vertex3f, -5, -1, -50);
    CMD0(&s, End);
    run(ip, &s);
    /* one planar run: GL's lambda per pixel, so no note (branch finish22) */
    CHECK_EQ_U(count(DIAG_NOTE_TEX_MIPMAP), 0);
    CHECK_EQ_U(sc.nmeshes, 1);
    if (sc.nmeshes == 1 && sc.meshes[0].tri_count == 2) {
        const scene_mesh *m = &sc.meshes[0];
        scene_mip_run r;
        const scene_texture *t = &sc.textures[m->look.texture];
        size_t n = scene_mip_split(&sc.camera, m->in_eye ? NULL : &m->to_eye, sc.verts,
                                sc.tris + m->first_tri, 2, t->width, t->height, &r);
        CHECK_EQ_U(n, 2);
        CHECK(r.planar);
    }
    interp_end_frame(ip);
    povwriter *w = povwriter_create();
    write_sdl_with(w, NULL);
    CHECK(strstr(sdl, "#declare rgl_mip0l=function(x,y){ln(") != NULL);
    CHECK(strstr(sdl, "uv_mapping function{min(") != NULL);
    CHECK_EQ_U(povwriter_image(w, 4) != NULL, 1); /* 16, 8, 4, 2, 1 */
    CHECK(povwriter_image(w, 5) == NULL);
    CHECK(strstr(sdl, "nan") == NULL && strstr(sdl, "inf") == NULL);
    povwriter_destroy(w);
    interp_destroy(ip);
    free_res();
}

/* Cube maps: the six faces are accepted (no "invalid texture target"),
 * the draw's texture is +X linked to the other five, the vertices carry
 * (s, t, r) from GL_REFLECTION_MAP (r in tex1), a missing face leaves the
 * cube incomplete, and the writer samples the faces by the major axis. */
static void test_cube(void)
{
    uint8_t face[6][4 * 3];
    uint32_t id[6];
    for (int k = 0; k < 6; k++) {
        memset(face[k], 40 * k, sizeof face[k]);
        id[k] = add_bytes(face[k], sizeof face[k]);
    }
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Viewport, 0, 0, 100, 100);
    CMD(&s, BindTexture, GL_TEXTURE_CUBE_MAP, 7);
    for (int k = 0; k < 5; k++)
        CMD(&s, TexImage2D, GL_TEXTURE_CUBE_MAP_POSITIVE_X + k, 0, GL_RGB, 2, 2, 0, GL_RGB,
            GL_UNSIGNED_BYTE, id[k]);
    CMD(&s, TexParameteri, GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    CMD(&s, TexEnvi, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    CMD(&s, Enable, GL_TEXTURE_CUBE_MAP);
    for (int c = 0; c < 3; c++) {
        CMD(&s, TexGeni, GL_S + c, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
        CMD(&s, Enable, GL_TEXTURE_GEN_S + c);
    }
    CMD(&s, Normal3f, 0, 0, 1);
    triangle(&s); /* five faces: incomplete */
    CMD(&s, TexImage2D, GL_TEXTURE_CUBE_MAP_NEGATIVE_Z, 0, GL_RGB, 2, 2, 0, GL_RGB,
        GL_UNSIGNED_BYTE, id[5]);
    triangle(&s);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_GL_INVALID_ENUM), 0);
    CHECK_EQ_U(sc.nmeshes, 2);
    if (sc.nmeshes == 2) {
        CHECK(sc.meshes[0].look.texture == -1);
        int32_t t = sc.meshes[1].look.texture;
        CHECK(t >= 0 && sc.textures[t].cube);
        int n = 0;
        for (int32_t k = t; k >= 0 && n < 7; k = sc.textures[k].mip_next, n++)
            CHECK_EQ_U(sc.textures[k].rgba[0], 40 * n);
        CHECK_EQ_U(n, 6);
        /* GL 2.10.4: at eye (1, 0, 0), normal +Z: u = (1, 0, 0), r = u. */
        const scene_tri *tr = &sc.tris[sc.meshes[1].first_tri];
        for (int k = 0; k < 3; k++) {
            const scene_vertex *v = &sc.verts[tr->v[k]];
            if (v->pos[0] == 1 && v->pos[1] == 0)
                CHECK(v->tex[0] == 1 && v->tex[1] == 0 && v->tex1[0] == 0);
        }
    }
    interp_end_frame(ip);
    povwriter *w = povwriter_create();
    write_sdl_with(w, NULL);
    CHECK(strstr(sdl, "#declare rgl_cube0f5=function{pigment{image_map{") != NULL);
    CHECK(strstr(sdl, "#declare rgl_cube0c2=function(x,y,z){select(min(abs(x)-abs(y),abs(x)-abs(z))") != NULL);
    CHECK_EQ_U(occurrences(sdl, "#declare rgl_cube0c"), 3); /* once per cube, not per run */
    CHECK(strstr(sdl, "function{min(1,max(0,rgl_cube0c0(x,y,") != NULL);
    CHECK(strstr(sdl, "nan") == NULL && strstr(sdl, "inf") == NULL);
    povwriter_destroy(w);
    interp_destroy(ip);
    /* A face that is not square is GL_INVALID_VALUE; the proxy is ignored. */
    ip = fresh();
    seq_init(&s);
    CMD(&s, BindTexture, GL_TEXTURE_CUBE_MAP, 1);
    CMD(&s, TexImage2D, GL_TEXTURE_CUBE_MAP_POSITIVE_Y, 0, GL_RGB, 4, 1, 0, GL_RGB,
        GL_UNSIGNED_BYTE, id[0]);
    CMD(&s, TexImage2D, GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_RGB, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, 0);
    /* glTexSubImage2D of a face patches that face */
    for (int k = 0; k < 6; k++)
        CMD(&s, TexImage2D, GL_TEXTURE_CUBE_MAP_POSITIVE_X + k, 0, GL_RGB, 2, 2, 0, GL_RGB,
            GL_UNSIGNED_BYTE, id[k]);
    uint8_t red[3] = {255, 0, 0};
    uint32_t ir = add_bytes(red, sizeof red);
    CMD(&s, TexSubImage2D, GL_TEXTURE_CUBE_MAP_NEGATIVE_Y, 0, 1, 1, 1, 1, GL_RGB, GL_UNSIGNED_BYTE, ir);
    CMD(&s, TexParameteri, GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    CMD(&s, Enable, GL_TEXTURE_CUBE_MAP);
    triangle(&s);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_GL_INVALID_VALUE), 1);
    CHECK_EQ_U(count(DIAG_GL_INVALID_ENUM), 0);
    CHECK_EQ_U(count(DIAG_GL_INVALID_OPERATION), 0);
    if (sc.nmeshes == 1 && sc.meshes[0].look.texture >= 0) {
        int32_t k = sc.meshes[0].look.texture;
        for (int f = 0; f < 3 && k >= 0; f++)
            k = sc.textures[k].mip_next; /* -Y */
        if (k >= 0)
            CHECK(sc.textures[k].rgba[(1 * 2 + 1) * 4] == 255 && sc.textures[k].rgba[0] == 120);
    } else {
        CHECK(0);
    }
    interp_destroy(ip);
    free_res();
}

/* GL_CLAMP blends the border under a linear filter: the writer samples
 * GL's filter every half texel, so no note; only a mipmapped one, whose
 * levels are padded with the edge texels' mix, is noted. GL_CLAMP_TO_EDGE
 * and GL_CLAMP under GL_NEAREST are exact: no note. */
static void test_clamp_border(void)
{
    static const GLenum wraps[4] = {GL_CLAMP, GL_CLAMP_TO_EDGE, GL_CLAMP, GL_CLAMP};
    static const GLenum filters[4] = {GL_LINEAR, GL_LINEAR, GL_NEAREST, GL_LINEAR_MIPMAP_LINEAR};
    uint32_t id = add_bytes(px, sizeof px), id1 = add_bytes(px, 4);
    for (int c = 0; c < 4; c++) {
        interp *ip = fresh();
        seq s;
        seq_init(&s);
        texture(&s, id, GL_REPLACE, wraps[c]);
        if (c == 3)
            CMD(&s, TexImage2D, GL_TEXTURE_2D, 1, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, id1);
        CMD(&s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filters[c] == GL_NEAREST ? GL_NEAREST : GL_LINEAR);
        CMD(&s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filters[c]);
        triangle(&s);
        run(ip, &s);
        CHECK_EQ_U(count(DIAG_NOTE_TEX_CLAMP_BORDER), c == 3 ? 1 : 0);
        CHECK(sc.nmeshes == 1 && sc.meshes[0].look.texture >= 0);
        interp_destroy(ip);
    }
}

/* GL_TEXTURE_LOD_BIAS of the object plus the unit's (glTexEnv
 * GL_TEXTURE_FILTER_CONTROL), clamped to GL_MAX_TEXTURE_LOD_BIAS (16), on
 * each level of the chain; the writer adds it to lambda before the clamp
 * to GL_TEXTURE_MIN_LOD (written as level min_lod / (n - 1), not 0). */
static void test_lod_bias(void)
{
    uint8_t a[2 * 2 * 3], b[3];
    memset(a, 200, sizeof a);
    memset(b, 50, sizeof b);
    uint32_t ia = add_bytes(a, sizeof a), ib = add_bytes(b, sizeof b);
    static const float obj[3] = {1.5f, 20, 0.5f}, unit[3] = {0, 0, -1}, want[3] = {1.5f, 16, -0.5f};
    for (int c = 0; c < 3; c++) {
        interp *ip = fresh();
        seq s;
        seq_init(&s);
        CMD(&s, BindTexture, GL_TEXTURE_2D, 1);
        CMD(&s, Enable, GL_TEXTURE_2D);
        CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_RGB, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, ia);
        CMD(&s, TexImage2D, GL_TEXTURE_2D, 1, GL_RGB, 1, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, ib);
        CMD(&s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_LINEAR);
        CMD(&s, TexParameterf, GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, obj[c]);
        CMD(&s, TexParameterf, GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, 0.5);
        CMD(&s, TexEnvf, GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, unit[c]);
        triangle(&s);
        run(ip, &s);
        int32_t t = sc.nmeshes == 1 ? sc.meshes[0].look.texture : -1;
        CHECK(t >= 0 && sc.textures[t].mip_next >= 0);
        if (t >= 0) {
            CHECK_NEAR(sc.textures[t].lod_bias, want[c], 1e-6);
            if (sc.textures[t].mip_next >= 0)
                CHECK_NEAR(sc.textures[sc.textures[t].mip_next].lod_bias, want[c], 1e-6);
        }
        write_sdl();
        /* The triangle's lambda varies under 1/16 level: one lambda for it
         * (povwrite_mipmap.c), lambda + bias clamped to [0.5, 1] over one
         * level: 0.5 under the bias 1.5 and -0.5 (lambda below -1, the
         * MIN_LOD start, not 0), 1 under 16. A function of the pixel where
         * lambda varies carries the bias as a term. */
        static const char *const bias[3] = {"+(1.5)))", "+(16)))", "+(-0.5)))"};
        static const char *const flat[3] = {"uv_mapping function{(0.5)}", "uv_mapping function{(1)}",
                                            "uv_mapping function{(0.5)}"};
        const char *f = strstr(sdl, "uv_mapping function{min((1),max((0.5),rgl_mip0l(x,y)");
        CHECK(f ? strncmp(f + strlen("uv_mapping function{min((1),max((0.5),rgl_mip0l(x,y)"), bias[c],
                          strlen(bias[c])) == 0
                : strstr(sdl, flat[c]) != NULL);
        interp_destroy(ip);
    }
    free_res();
}

/* GL_COMPARE_R_TO_TEXTURE: with r constant over the triangle the texels
 * are the comparison's results (GL_LEQUAL, r 0.5: depth 0.2 fails, 0.8
 * passes), no note; with r varying the depths are drawn, noted. */
static void test_compare(void)
{
    static const float depth[2] = {0.2f, 0.8f};
    uint32_t id = add_bytes(depth, sizeof depth);
    for (int c = 0; c < 2; c++) {
        interp *ip = fresh();
        seq s;
        seq_init(&s);
        CMD(&s, BindTexture, GL_TEXTURE_2D, 1);
        CMD(&s, Enable, GL_TEXTURE_2D);
        CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 2, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, id);
        CMD(&s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        CMD(&s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
        CMD(&s, Begin, GL_TRIANGLES);
        CMD(&s, TexCoord3f, 0, 0, 0.5);
        CMD(&s, Vertex2f, 0, 0);
        CMD(&s, TexCoord3f, 1, 0, c ? 0.6 : 0.5);
        CMD(&s, Vertex2f, 1, 0);
        CMD(&s, TexCoord3f, 0, 1, 0.5);
        CMD(&s, Vertex2f, 0, 1);
        CMD0(&s, End);
        run(ip, &s);
        CHECK_EQ_U(count(DIAG_NOTE_TEX_COMPARE), c);
        int32_t t = sc.nmeshes == 1 ? sc.meshes[0].look.texture : -1;
        CHECK(t >= 0);
        if (t >= 0 && c == 0)
            CHECK(sc.textures[t].rgba[0] == 0 && sc.textures[t].rgba[4] == 255);
        if (t >= 0 && c == 1) /* the depths: 51, 204 */
            CHECK(sc.textures[t].rgba[0] == 51 && sc.textures[t].rgba[4] == 204);
        interp_destroy(ip);
    }
    free_res();
}

int main(void)
{
    scene_init(&sc);
    fx_fetch = fetch_res;
    test_mirrored();
    test_modulate_tint();
    test_blend_add();
    test_alpha_test();
    test_levels();
    test_mip_runs();
    test_cube();
    test_clamp_border();
    test_lod_bias();
    test_compare();
    scene_finish(&sc);
    return CHECK_RESULT("test_tex_env");
}
