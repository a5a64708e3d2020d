/* test_textures.c: textures in the interpreter and the writer (issue 5).
 *
 * Pixel conversion of each format and type into GL's texels, bottom row
 * first, with the trace's pixels taken as tightly packed whatever
 * glPixelStorei says (the recorder has unpacked them); hostile sizes and
 * short pixel data as errors, not crashes or huge allocations; texture
 * completeness; glTexSubImage2D and copies of the state (copy on write);
 * textures defined inside display lists; texgen's formulas; and the
 * images the writer names: one PNG per content, written once, the right
 * way up, clamp padding.
 */
#include <GL/gl.h>
#include <dirent.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "check.h"
#include "interp_fixture.h"
#include "interp.h"
#include "outbuf.h"
#include "pngout.h"
#include "povwrite.h"
#include "povwrite_texture.h"
#include "tracegen.h"

/* Nearest filters (a complete texture without mipmaps), texturing on. */
static void setup(seq *s, GLenum target, uint32_t name)
{
    CMD(s, BindTexture, target, name);
    CMD(s, TexParameteri, target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    CMD(s, TexParameteri, target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    CMD(s, Enable, target);
}

static void triangle(seq *s)
{
    CMD(s, Begin, GL_TRIANGLES);
    CMD(s, TexCoord2f, 0, 0);
    CMD(s, Vertex2f, 0, 0);
    CMD(s, TexCoord2f, 1, 0);
    CMD(s, Vertex2f, 1, 0);
    CMD(s, TexCoord2f, 0, 1);
    CMD(s, Vertex2f, 0, 1);
    CMD0(s, End);
}

static int32_t last_texture(void)
{
    return sc.nmeshes ? sc.meshes[sc.nmeshes - 1].look.texture : -2;
}

static void test_formats(void)
{
    /* RGB 3 x 2 bytes, tightly packed (rows of 9 bytes), after an
     * alignment of 4 in the trace: it must not be applied again. */
    const uint8_t rgb[18] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18};
    uint32_t id = add_bytes(rgb, sizeof rgb);
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, PixelStorei, GL_UNPACK_ALIGNMENT, 4);
    CMD(&s, PixelStorei, GL_UNPACK_ROW_LENGTH, 7);
    setup(&s, GL_TEXTURE_2D, 5);
    CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_RGB8, 3, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, id);
    triangle(&s);
    run(ip, &s);
    CHECK_EQ_U(sc.ntextures, 1);
    CHECK_EQ_U(last_texture(), 0);
    if (sc.ntextures == 1) {
        const scene_texture *t = &sc.textures[0];
        CHECK_EQ_U(t->width, 3);
        CHECK_EQ_U(t->height, 2);
        /* texel (2, 1): bytes 15..17 of the tight rows, alpha 1 */
        const uint8_t *p = t->rgba + (1 * 3 + 2) * 4;
        CHECK(p[0] == 16 && p[1] == 17 && p[2] == 18 && p[3] == 255);
        CHECK(t->env_mode == SCENE_ENV_MODULATE && !t->colour_is_texel && t->repeat_s && !t->linear);
    }
    CHECK_EQ_U(count(DIAG_GL_INVALID_VALUE) + count(DIAG_IGNORED), 0);
    interp_destroy(ip);

    /* LUMINANCE floats (clamped), LUMINANCE_ALPHA shorts, ALPHA bytes. */
    const float lum[2] = {0.5f, 2.0f};
    const uint16_t la[4] = {0, 65535, 65535, 32768};
    const uint8_t al[2] = {0, 128};
    uint32_t idl = add_bytes(lum, sizeof lum), idla = add_bytes(la, sizeof la),
             ida = add_bytes(al, sizeof al);
    ip = fresh();
    seq_init(&s);
    setup(&s, GL_TEXTURE_2D, 1);
    CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_LUMINANCE, 2, 1, 0, GL_LUMINANCE, GL_FLOAT, idl);
    CMD(&s, TexEnvi, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    triangle(&s);
    setup(&s, GL_TEXTURE_2D, 2);
    CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, 2, 1, 0, GL_LUMINANCE_ALPHA,
        GL_UNSIGNED_SHORT, idla);
    triangle(&s);
    setup(&s, GL_TEXTURE_2D, 3);
    CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_ALPHA, 2, 1, 0, GL_ALPHA, GL_UNSIGNED_BYTE, ida);
    triangle(&s);
    run(ip, &s);
    CHECK_EQ_U(sc.ntextures, 3);
    if (sc.ntextures == 3) {
        const uint8_t *l = sc.textures[0].rgba, *a = sc.textures[1].rgba, *o = sc.textures[2].rgba;
        CHECK(l[0] == 128 && l[1] == 128 && l[2] == 128 && l[3] == 255);
        CHECK(l[4] == 255 && l[7] == 255);
        CHECK(sc.textures[0].colour_is_texel); /* REPLACE of luminance */
        CHECK(a[0] == 0 && a[3] == 255 && a[4] == 255 && a[7] == 128);
        /* ALPHA: the colour is the fragment's (texel rgb neutral 1) */
        CHECK(o[0] == 255 && o[1] == 255 && o[2] == 255 && o[3] == 0 && o[7] == 128);
        CHECK(!sc.textures[2].colour_is_texel); /* REPLACE of alpha keeps the colour */
    }
    interp_destroy(ip);
    free_res();
}

/* Sizes a hostile trace may claim: errors, never crashes or huge
 * allocations; pixel data of the wrong length is refused. */
static void test_hostile_sizes(void)
{
    const uint8_t px[16] = {0};
    uint32_t id = add_bytes(px, sizeof px);
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    setup(&s, GL_TEXTURE_2D, 1);
    CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 2147483647, 2147483647, 0, GL_RGBA,
        GL_UNSIGNED_BYTE, id);
    CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 16384, 16384, 0, GL_RGBA, GL_FLOAT, id);
    CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, -4, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, id);
    CMD(&s, TexImage1D, GL_TEXTURE_1D, 0, GL_RGBA, 2147483647, 0, GL_RGBA, GL_UNSIGNED_BYTE, id);
    CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 3, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, id); /* 36 > 16 bytes */
    CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, 999); /* no such pixels */
    CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, 12345, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, id);
    CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, 0x1234, GL_UNSIGNED_BYTE, id);
    CMD(&s, Build2DMipmaps, GL_TEXTURE_2D, GL_RGBA, 2147483647, 3, GL_RGBA, GL_UNSIGNED_BYTE, id);
    CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, id);
    CMD(&s, TexSubImage2D, GL_TEXTURE_2D, 0, 1, 1, 2147483647, 2, GL_RGBA, GL_UNSIGNED_BYTE, id);
    CMD(&s, TexSubImage2D, GL_TEXTURE_2D, 0, -1, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, id);
    CMD(&s, TexSubImage2D, GL_TEXTURE_2D, 0, 1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, id); /* 4 != 16 bytes */
    triangle(&s);
    run(ip, &s);
    CHECK(count(DIAG_GL_INVALID_VALUE) >= 7);
    CHECK(count(DIAG_GL_INVALID_ENUM) >= 1);
    CHECK(count(DIAG_IGNORED) >= 3);
    CHECK(!sc.failed);
    /* Only the valid 2 x 2 image remains, unchanged by the refused patches. */
    CHECK_EQ_U(sc.ntextures, 1);
    if (sc.ntextures == 1)
        CHECK(sc.textures[0].width == 2 && sc.textures[0].height == 2);
    interp_destroy(ip);
    free_res();
}

/* GL's default minification filter mipmaps: level 0 alone is incomplete
 * and draws untextured; gluBuild2DMipmaps completes the chain (and scales
 * a size that is not a power of two). */
static void test_completeness(void)
{
    uint8_t px[6 * 4 * 3];
    for (size_t i = 0; i < sizeof px; i++)
        px[i] = (uint8_t)(i * 7);
    uint32_t id = add_bytes(px, sizeof px);
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, BindTexture, GL_TEXTURE_2D, 1);
    CMD(&s, Enable, GL_TEXTURE_2D);
    CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_RGB, 6, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, id);
    triangle(&s);
    run(ip, &s);
    CHECK_EQ_U(last_texture(), (uint64_t)-1);
    seq_init(&s);
    CMD(&s, Build2DMipmaps, GL_TEXTURE_2D, GL_RGB, 6, 4, GL_RGB, GL_UNSIGNED_BYTE, id);
    triangle(&s);
    run(ip, &s);
    /* The levels are scene textures of their own, the last first: 1 x 1,
     * 2 x 1, 4 x 2, then level 0, linked by mip_next. */
    CHECK_EQ_U(last_texture(), 3);
    if (sc.ntextures == 4) { /* 6 is scaled to 8 (nearest power in log scale), 4 stays */
        CHECK(sc.textures[3].width == 8 && sc.textures[3].height == 4);
        CHECK(sc.textures[3].mip_next == 2 && sc.textures[2].width == 4);
        CHECK(sc.textures[0].mip_next == -1 && sc.textures[0].width == 1);
    }
    interp_destroy(ip);
    free_res();
}

/* glTexSubImage2D after a copy of the state changes the copy only; a
 * deleted texture unbinds; textures defined in a display list. */
static void test_copies_lists(void)
{
    const uint8_t red[4] = {255, 0, 0, 255}, blue[16] = {0, 0, 255, 255, 0, 0, 255, 255,
                                                          0, 0, 255, 255, 0, 0, 255, 255};
    uint32_t idr = add_bytes(red, 4), idb = add_bytes(blue, 16);
    seq body;
    seq_init(&body);
    setup(&body, GL_TEXTURE_2D, 7);
    CMD(&body, TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, idb);
    uint32_t list = add_res_body(&body);

    interp *a = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, NewList, 1, GL_COMPILE, list);
    CMD0(&s, EndList);
    CMD(&s, CallList, 1);
    run(a, &s);
    scene_reset(&sc);
    interp_begin_frame(a);
    seq_init(&s);
    triangle(&s);
    run(a, &s);
    CHECK_EQ_U(last_texture(), 0);
    if (sc.ntextures == 1)
        CHECK(sc.textures[0].rgba[2] == 255 && sc.textures[0].rgba[0] == 0);

    interp *b = interp_create(NULL, NULL);
    interp_set_resources(b, fetch_res, NULL);
    interp_copy_state(b, a);
    seq_init(&s);
    CMD(&s, TexSubImage2D, GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, idr);
    run(b, &s);
    /* a still draws blue */
    scene_reset(&sc);
    interp_begin_frame(a);
    seq_init(&s);
    triangle(&s);
    run(a, &s);
    if (sc.ntextures == 1)
        CHECK(sc.textures[0].rgba[0] == 0 && sc.textures[0].rgba[2] == 255);
    /* b draws the patch */
    interp_attach(b, &sc, &dlog);
    scene_reset(&sc);
    interp_begin_frame(b);
    seq_init(&s);
    triangle(&s);
    CMD(&s, DeleteTextures, 7);
    triangle(&s); /* object 0 has no image: untextured */
    run(b, &s);
    CHECK_EQ_U(sc.ntextures, 1);
    if (sc.ntextures == 1)
        CHECK(sc.textures[0].rgba[0] == 255 && sc.textures[0].rgba[2] == 0 &&
              sc.textures[0].rgba[6] == 255);
    CHECK_EQ_U(last_texture(), (uint64_t)-1);
    interp_destroy(a);
    interp_destroy(b);
    free_res();
}

/* Texgen: object and eye planes (the eye plane through the inverse of the
 * modelview at the call) and the sphere map's formula, then the texture
 * matrix. */
static void test_texgen(void)
{
    const uint8_t px[4] = {1, 2, 3, 255};
    uint32_t id = add_bytes(px, 4);
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    setup(&s, GL_TEXTURE_2D, 1);
    CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, id);
    CMD(&s, TexGeni, GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    CMD(&s, TexGenfv, GL_S, GL_OBJECT_PLANE, 2, 0, 0, 1);
    CMD(&s, Translatef, 10, 0, 0);
    CMD(&s, TexGeni, GL_T, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    CMD(&s, TexGenfv, GL_T, GL_EYE_PLANE, 1, 0, 0, 0); /* eye x, as object x + 10 */
    CMD0(&s, LoadIdentity);
    CMD(&s, Translatef, 3, 0, 0);
    CMD(&s, Enable, GL_TEXTURE_GEN_S);
    CMD(&s, Enable, GL_TEXTURE_GEN_T);
    CMD(&s, Begin, GL_TRIANGLES);
    CMD(&s, Vertex2f, 1, 0);
    CMD(&s, Vertex2f, 2, 0);
    CMD(&s, Vertex2f, 1, 1);
    CMD0(&s, End);
    run(ip, &s);
    CHECK_EQ_U(sc.nverts, 3);
    if (sc.nverts == 3) {
        CHECK_NEAR(sc.verts[0].tex[0], 3, 1e-6);  /* 2 * 1 + 1 */
        CHECK_NEAR(sc.verts[0].tex[1], -6, 1e-6); /* eye x 4 in the plane's space: 4 - 10 */
        CHECK_NEAR(sc.verts[1].tex[0], 5, 1e-6);
    }
    /* Sphere map: a vertex straight ahead (u = (0, 0, -1)) with normal
     * (0, 0, 1): r = (0, 0, 1), m = 4, (s, t) = (1/2, 1/2); normal
     * (0.6, 0, 0.8): r = u - 2n(n.u) = (0.96, 0, 0.28), m = 2 sqrt(0.9216 +
     * 1.6384), s = 0.96/m + 1/2. Then the texture matrix scales s by 2. */
    seq_init(&s);
    CMD0(&s, LoadIdentity);
    CMD(&s, TexGeni, GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
    CMD(&s, TexGeni, GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
    CMD(&s, Begin, GL_TRIANGLES);
    CMD(&s, Normal3f, 0, 0, 1);
    CMD(&s, Vertex3f, 0, 0, -5);
    CMD(&s, Normal3f, 0.6, 0, 0.8);
    CMD(&s, Vertex3f, 0, 0, -5);
    CMD(&s, Vertex3f, 1, 0, -5);
    CMD0(&s, End);
    CMD(&s, MatrixMode, GL_TEXTURE);
    CMD(&s, Scalef, 2, 1, 1);
    CMD(&s, MatrixMode, GL_MODELVIEW);
    CMD(&s, Begin, GL_TRIANGLES);
    CMD(&s, Normal3f, 0.6, 0, 0.8);
    CMD(&s, Vertex3f, 0, 0, -5);
    CMD(&s, Vertex3f, 1, 0, -5);
    CMD(&s, Vertex3f, 0, 1, -5);
    CMD0(&s, End);
    CMD(&s, TexGeni, GL_Q, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP); /* not for q */
    run(ip, &s);
    CHECK_EQ_U(sc.nverts, 9);
    if (sc.nverts == 9) {
        double m = 2 * sqrt(0.9216 + 1.6384);
        CHECK_NEAR(sc.verts[3].tex[0], 0.5, 1e-6);
        CHECK_NEAR(sc.verts[3].tex[1], 0.5, 1e-6);
        CHECK_NEAR(sc.verts[4].tex[0], 0.96 / m + 0.5, 1e-5);
        CHECK_NEAR(sc.verts[4].tex[1], 0.5, 1e-6);
        CHECK_NEAR(sc.verts[6].tex[0], 2 * (0.96 / m + 0.5), 1e-5);
    }
    CHECK(count(DIAG_GL_INVALID_ENUM) == 1);
    interp_destroy(ip);
    free_res();
}

/* Reads a PNG: width, height, first (top) row's first pixel. */
static int read_png(const char *path, unsigned *w, unsigned *h, uint8_t top[3], uint8_t bottom[3])
{
    png_image im;
    memset(&im, 0, sizeof im);
    im.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&im, path))
        return -1;
    im.format = PNG_FORMAT_RGB;
    uint8_t *buf = malloc(PNG_IMAGE_SIZE(im));
    if (!buf || !png_image_finish_read(&im, NULL, buf, 0, NULL)) {
        free(buf);
        png_image_free(&im);
        return -1;
    }
    *w = im.width;
    *h = im.height;
    memcpy(top, buf, 3);
    memcpy(bottom, buf + (size_t)(im.height - 1) * im.width * 3, 3);
    free(buf);
    return 0;
}

static size_t count_files(const char *dir, const char *prefix)
{
    DIR *d = opendir(dir);
    size_t n = 0;
    struct dirent *e;
    while (d && (e = readdir(d)))
        n += strncmp(e->d_name, prefix, strlen(prefix)) == 0;
    if (d)
        closedir(d);
    return n;
}

static int discard(void *user, const char *p, size_t n)
{
    (void)user;
    (void)p;
    (void)n;
    return 0;
}

/* The writer: one image per content within and across frames, files
 * written once and the right way up (file top row = t = 1), clamped axes
 * padded with their edge, the SDL naming the file. */
static void test_images(void)
{
    char dir[] = "/tmp/rgl-textest-XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    /* 2 x 2: bottom row green, top row red */
    const uint8_t px[16] = {0, 255, 0, 255, 0, 255, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255};
    uint32_t id = add_bytes(px, 16);
    povwriter *w = povwriter_create();
    outbuf ob;
    CHECK(outbuf_init(&ob, 1 << 16, discard, NULL) == 0);
    char first[POVTEX_NAME_MAX] = "";
    struct stat st0;
    memset(&st0, 0, sizeof st0);
    for (int frame = 0; frame < 2; frame++) {
        interp *ip = fresh();
        seq s;
        seq_init(&s);
        CMD(&s, Viewport, 0, 0, 100, 100);
        setup(&s, GL_TEXTURE_2D, 1);
        CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, id);
        triangle(&s);
        CMD(&s, Translatef, 0.1, 0, 0); /* another mesh, the same image */
        triangle(&s);
        run(ip, &s);
        interp_end_frame(ip);
        CHECK(povwriter_scene(w, &ob, &sc, NULL) == 0);
        const povtex_image *im = povwriter_image(w, 0);
        CHECK(im != NULL && povwriter_image(w, 1) == NULL);
        if (im) {
            CHECK(pngout_place(dir, im->name, im->rgba, im->width, im->height, im->alpha) == 0);
            if (frame == 0) {
                snprintf(first, sizeof first, "%s", im->name);
                char path[256];
                snprintf(path, sizeof path, "%s/%s", dir, im->name);
                CHECK(stat(path, &st0) == 0);
                unsigned pw = 0, ph = 0;
                uint8_t top[3] = {0, 0, 0}, bot[3] = {0, 0, 0};
                CHECK(read_png(path, &pw, &ph, top, bot) == 0);
                CHECK(pw == 2 && ph == 2);
                CHECK(top[0] == 255 && top[1] == 0 && bot[1] == 255 && bot[0] == 0);
            } else {
                CHECK(strcmp(first, im->name) == 0);
            }
        }
        interp_destroy(ip);
    }
    char path[256];
    snprintf(path, sizeof path, "%s/%s", dir, first);
    struct stat st1;
    CHECK(stat(path, &st1) == 0 && st1.st_ino == st0.st_ino); /* not written again */
    CHECK_EQ_U(count_files(dir, "rgl-tex-"), 1);
    CHECK_EQ_U(count_files(dir, ".raygl2pov"), 0);
    /* Names that would leave the folder are refused. */
    CHECK(pngout_place(dir, "../x.png", px, 2, 2, false) != 0);
    CHECK(pngout_place(dir, "", px, 2, 2, false) != 0);

    /* Clamp: coordinates -0.5 .. 1.5 reach tiles -1 .. 2: 3 tiles of 2
     * texels and one edge texel each side, the texture in the middle. */
    scene_reset(&sc);
    scene_texture t;
    memset(&t, 0, sizeof t);
    t.width = t.height = 2;
    t.rgba = malloc(16);
    memcpy(t.rgba, px, 16);
    t.repeat_s = false;
    t.repeat_t = true;
    CHECK(scene_add_texture(&sc, &t) == 0);
    povtex pt;
    memset(&pt, 0, sizeof pt);
    float lo[2] = {-0.5f, -0.5f}, hi[2] = {1.5f, 1.5f}, scale[2], off[2];
    CHECK(povtex_map(&pt, &sc, 0, lo, hi, false, NULL, scale, off) == 0);
    if (pt.n == 1) {
        CHECK(pt.imgs[0].width == 8 && pt.imgs[0].height == 2);
        CHECK_NEAR(0 * scale[0] + off[0], 3.0 / 8, 1e-6); /* s = 0: after 1 + 2 texels */
        CHECK_NEAR(1 * scale[0] + off[0], 5.0 / 8, 1e-6);
        CHECK_NEAR(scale[1], 1, 0);
        /* the padded row: the texture's bottom-left texel out to the left */
        CHECK(pt.imgs[0].rgba[1] == 255 && pt.imgs[0].rgba[0] == 0);
    }
    povtex_finish(&pt);
    povwriter_destroy(w);
    outbuf_finish(&ob);
    unlink(path);
    rmdir(dir);
    free_res();
}

/* Two units: the look holds both textures, the writer one pigment
 * combining them (a function per image), one mesh2 per run of triangles
 * whose unit 1 coordinates follow one affine map of unit 0's; a unit 0
 * whose texture is incomplete passes its input on: unit 1 alone, with its
 * own coordinates. */
static void test_multitex(void)
{
    const uint8_t px[16] = {0, 255, 0, 255, 0, 255, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255};
    uint32_t id = add_bytes(px, 16);
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Viewport, 0, 0, 100, 100);
    setup(&s, GL_TEXTURE_2D, 1);
    CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, id);
    CMD(&s, ActiveTexture, GL_TEXTURE1);
    setup(&s, GL_TEXTURE_2D, 2);
    CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_RGB, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, id);
    CMD(&s, TexEnvi, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
    /* Two triangles of one primitive: unit 1's coordinates one map of
     * unit 0's over the first, another over the second: two runs. */
    static const float q[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    CMD(&s, Begin, GL_TRIANGLES);
    for (int i = 0; i < 3; i++) {
        CMD(&s, MultiTexCoord2f, GL_TEXTURE0, q[i][0] * 2, q[i][1] * 2);
        CMD(&s, MultiTexCoord2f, GL_TEXTURE1, q[i][1], q[i][0]);
        CMD(&s, Vertex2f, q[i][0], q[i][1]);
    }
    for (int i = 1; i < 4; i++) {
        CMD(&s, MultiTexCoord2f, GL_TEXTURE0, q[i][0], q[i][1]);
        CMD(&s, MultiTexCoord2f, GL_TEXTURE1, q[i][0] * 3, q[i][1]);
        CMD(&s, Vertex2f, q[i][0], q[i][1]);
    }
    CMD0(&s, End);
    run(ip, &s);
    CHECK_EQ_U(sc.nmeshes, 1);
    if (sc.nmeshes) {
        CHECK(sc.meshes[0].look.texture >= 0 && sc.meshes[0].look.texture1 >= 0);
        CHECK(sc.meshes[0].look.texture != sc.meshes[0].look.texture1);
        if (sc.meshes[0].look.texture1 >= 0)
            CHECK_EQ_U(sc.textures[sc.meshes[0].look.texture1].env_mode, SCENE_ENV_ADD);
    }
    interp_end_frame(ip);
    write_sdl();
    CHECK_EQ_U(occurrences(sdl, "mesh2{"), 2);
    CHECK_EQ_U(occurrences(sdl, "#declare rgl_mt0a=function{pigment{image_map{"), 1);
    CHECK_EQ_U(occurrences(sdl, "#declare rgl_mt1b=function{pigment{image_map{"), 1);
    CHECK_EQ_U(occurrences(sdl, "uv_mapping average pigment_map{"), 2);
    CHECK(strstr(sdl, "min(1,") != NULL); /* GL_ADD clamps */
    CHECK(strstr(sdl, "nan") == NULL && strstr(sdl, "inf") == NULL);
    interp_destroy(ip);

    /* Unit 0 enabled with no texture: unit 1 alone, on its coordinates. */
    ip = fresh();
    seq_init(&s);
    CMD(&s, Viewport, 0, 0, 100, 100);
    CMD(&s, Enable, GL_TEXTURE_2D);
    CMD(&s, ActiveTexture, GL_TEXTURE1);
    setup(&s, GL_TEXTURE_2D, 2);
    CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_RGB, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, id);
    CMD(&s, Begin, GL_TRIANGLES);
    for (int i = 0; i < 3; i++) {
        CMD(&s, MultiTexCoord2f, GL_TEXTURE1, 0.5, q[i][1]);
        CMD(&s, Vertex2f, q[i][0], q[i][1]);
    }
    CMD0(&s, End);
    run(ip, &s);
    CHECK_EQ_U(sc.nmeshes, 1);
    if (sc.nmeshes) {
        CHECK(sc.meshes[0].look.texture >= 0 && sc.meshes[0].look.texture1 < 0);
        CHECK_NEAR(sc.verts[2].tex[0], 0.5, 0);
        CHECK_NEAR(sc.verts[2].tex[1], 1, 0);
    }
    interp_destroy(ip);
    free_res();
}

/* Issue 22: the texture budget counts each image once a frame, however
 * often it is drawn; what is new (rewritten texels, another slice) is
 * still counted every time, so a hostile trace stays bounded. */
static void test_budget_once(void)
{
    enum { T = 64, N = 10000 };
    static uint8_t px[T * T * 4], other[T * T * 4];
    for (size_t i = 0; i < sizeof px; i++) {
        px[i] = (uint8_t)(i * 7 + (i >> 8));
        other[i] = (uint8_t)(px[i] ^ 0x5a);
    }
    uint32_t id = add_bytes(px, sizeof px), id2 = add_bytes(other, sizeof other);
    uint32_t rect = add_bytes(px, 16 * 16 * 4);
    /* The levels' bytes: 64 x 64 down to 1 x 1, 4 bytes a texel. */
    uint64_t chain = 0;
    for (int s0 = T; s0 >= 1; s0 /= 2)
        chain += (uint64_t)s0 * (uint64_t)s0 * 4;
    interp_budget_use used, limit;

    /* A mipmapped texture drawn N times, each triangle its own primitive. */
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, BindTexture, GL_TEXTURE_2D, 1);
    CMD(&s, TexParameteri, GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    CMD(&s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, T, T, 0, GL_RGBA, GL_UNSIGNED_BYTE, id);
    CMD(&s, Enable, GL_TEXTURE_2D);
    for (int i = 0; i < N; i++)
        triangle(&s);
    run(ip, &s);
    interp_budget_used(ip, &used, &limit);
    CHECK(interp_frame_cut(ip) == NULL);
    CHECK_EQ_U(sc.ntextures, 7);
    /* The upload (read, converted, its levels made) and one copy of the
     * levels for the scene: what a single draw costs. */
    uint64_t once = 2 * (uint64_t)T * T * 4 + (chain - (uint64_t)T * T * 4) + chain;
    CHECK_EQ_U(used.texels, once);
    CHECK_EQ_U(limit.texels, INTERP_BUDGET_TEXELS);
    /* N draws of one primitive, texture or not, are N meshes' worth. */
    CHECK(used.triangles == N && used.assembled == 3 * N);

    /* Texels rewritten before each draw: every draw holds another image. */
    seq_init(&s);
    for (int i = 0; i < 100; i++) {
        CMD(&s, TexSubImage2D, GL_TEXTURE_2D, 0, 0, 0, T, T, GL_RGBA, GL_UNSIGNED_BYTE,
            i % 2 ? id : id2);
        triangle(&s);
    }
    run(ip, &s);
    uint64_t before = used.texels;
    interp_budget_used(ip, &used, &limit);
    CHECK(used.texels - before >= 100 * chain);
    interp_destroy(ip);

    /* A pixel rectangle drawn N times is read and converted once; each
     * draw costs the pixels it writes. */
    ip = fresh();
    seq_init(&s);
    CMD(&s, Viewport, 0, 0, 320, 240);
    CMD(&s, RasterPos2f, 0, 0);
    for (int i = 0; i < N; i++)
        CMD(&s, DrawPixels, 16, 16, GL_RGBA, GL_UNSIGNED_BYTE, rect);
    run(ip, &s);
    interp_budget_used(ip, &used, &limit);
    CHECK(interp_frame_cut(ip) == NULL);
    /* the overlay, one read and conversion, N x 256 pixels written */
    CHECK_EQ_U(used.texels, 320 * 240 * 4 + 16 * 16 * 4 + 16 * 16 * 16 + (uint64_t)N * 256);
    /* the rectangle's first pixel at the raster position, the window's centre */
    const uint8_t *o = sc.overlay ? sc.overlay + (120 * 320 + 160) * 4 : NULL;
    CHECK(o && o[0] == px[0] && o[1] == px[1] && o[2] == px[2]);
    interp_destroy(ip);

    /* A 3D texture at another r at every draw: a new slice each time. */
    ip = fresh();
    seq_init(&s);
    setup(&s, GL_TEXTURE_3D, 3);
    CMD(&s, TexImage3D, GL_TEXTURE_3D, 0, GL_RGBA, 16, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, id);
    for (int i = 0; i < 8; i++) {
        CMD(&s, TexCoord3f, 0, 0, (i % 4 + 0.5) / 16);
        CMD(&s, Rectf, 0, 0, 1, 1);
    }
    run(ip, &s);
    interp_budget_used(ip, &used, &limit);
    /* read and held (2 x 16 KiB), then 4 slices made and copied once each */
    CHECK_EQ_U(used.texels, 2 * 16384 + 4 * 2 * 1024);
    CHECK_EQ_U(sc.ntextures, 4);
    interp_destroy(ip);
    free_res();
}

int main(void)
{
    scene_init(&sc);
    fx_fetch = fetch_res;
    test_formats();
    test_hostile_sizes();
    test_completeness();
    test_copies_lists();
    test_texgen();
    test_images();
    test_multitex();
    test_budget_once();
    scene_finish(&sc);
    return CHECK_RESULT("test_textures");
}
