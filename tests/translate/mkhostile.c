/* mkhostile.c: writes the hostile traces test_bounds.sh feeds raygl2pov.
 *
 *   mkhostile DIR
 *
 * DIR/bomb-N.raygl    list 1 draws a triangle list of N vertices and calls
 *                     itself twice (issue 12: a few hundred bytes asking for
 *                     2^64 bodies); N = 3, 30, 300.
 * DIR/bomb-solid.raygl the same with a glutSolidSphere per call, and
 *                     DIR/bomb-empty.raygl with 4000 state calls per body and
 *                     no drawing (work without output).
 * DIR/bomb-lines.raygl the same with lines of 30 vertices, and
 *                     DIR/bomb-texture.raygl with a texture upload per call.
 * DIR/bomb-slices.raygl the same drawing another slice of a 3D texture per call.
 * DIR/honest-texture.raygl one mipmapped 256 x 256 texture drawn by 10240
 *                     triangles from lists: no cut, counted once (issue 22).
 * DIR/bomb-names.raygl 50000 textures and lists, then a list bomb of lookups.
 * DIR/texframes.raygl a texture uploaded and drawn in frame 0, drawn again in
 *                     frame 1 (STATE_CARRIED).
 * DIR/fill-all.raygl  two frames, each filling every output budget to just
 *                     under its bound (no cut): the most memory a frame can take.
 * DIR/heavy-redo.raygl a heavy frame (2^14 lists of 30 triangle vertices)
 *                     after a depth-tested quad of another projection:
 *                     raygl2pov translates it twice (the second time with
 *                     the perspective camera, interp_proj.c), heavy twice.
 * DIR/bomb-calls.raygl 100000 outermost calls of one small list (instances);
 *                     DIR/bomb-calls300.raygl 60000 calls of 300 vertices.
 * DIR/lists.raygl     two frames drawing through display lists (one nested),
 *                     the second with the lists and camera the first left
 *                     (STATE_CARRIED); small: test_bounds.sh changes each
 *                     of its bytes. The spans of list 1's body and of
 *                     frame 0's commands are printed as "list-body START
 *                     END" and "frame-0 START END".
 * DIR/unclosed.raygl  three frames, no index and no END trailer (the recorder
 *                     killed between frames); DIR/cut.raygl the same with a
 *                     fourth frame cut short in the middle (a full disk).
 * DIR/snap.raygl      three frames, each with an @Snapshot of one shared image
 *                     resource (as the recorder shares an unchanged picture);
 *                     the image's span printed as "snapshot-image START END".
 * DIR/snapshots.raygl four 8 x 6 frames with real snapshots, three sharing
 *                     one image (raygl-compare's test: compare/main.c).
 */
#include <GL/gl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tracegen.h"

static void camera(seq *s)
{
    CMD(s, Viewport, 0, 0, 64, 48);
    CMD(s, MatrixMode, GL_PROJECTION);
    CMD(s, Frustum, -1, 1, -0.75, 0.75, 1, 100);
    CMD(s, MatrixMode, GL_MODELVIEW);
    CMD(s, Translatef, 0, 0, -5);
    CMD(s, Enable, GL_DEPTH_TEST);
}

static void finish(rgl_trace_builder *b, bool with_index, const char *dir, const char *name)
{
    const uint8_t *data;
    size_t size;
    char path[4096];
    if (rgl_trace_builder_finish(b, with_index, &data, &size) != RGL_OK) {
        fprintf(stderr, "mkhostile: %s: cannot build\n", name);
        exit(1);
    }
    snprintf(path, sizeof path, "%s/%s", dir, name);
    write_file(path, data, size);
}

static uint32_t resource(rgl_trace_builder *b, uint32_t kind, const void *data, size_t size)
{
    uint32_t id;
    if (rgl_trace_builder_resource(b, kind, data, size, &id) != RGL_OK) {
        fprintf(stderr, "mkhostile: cannot add a resource\n");
        exit(1);
    }
    return id;
}

static void frame(rgl_trace_builder *b, uint32_t number, const seq *s)
{
    if (rgl_trace_builder_frame(b, 0, number, 0, 0, s->data, s->len) != RGL_OK) {
        fprintf(stderr, "mkhostile: cannot add a frame\n");
        exit(1);
    }
}

/* kind 0: a triangle list of n vertices; 1: a sphere; 2: n state calls;
 * 3: lines of n vertices. */
static void bomb(const char *dir, const char *name, int kind, int n)
{
    rgl_trace_builder *b = rgl_trace_builder_create();
    seq body, s;
    seq_init(&body);
    if (kind == 0 || kind == 3) {
        CMD(&body, Begin, kind == 0 ? GL_TRIANGLES : GL_LINES);
        for (int i = 0; i < n; i++)
            CMD(&body, Vertex3f, i % 3 == 1, i % 3 == 2, -(double)i / n);
        CMD0(&body, End);
    } else if (kind == 1) {
        CMD(&body, SolidSphere, 0.5, 8, 8);
    } else {
        for (int i = 0; i < n; i++)
            CMD(&body, Color3f, 1, 0.5, 0.25);
    }
    CMD(&body, CallList, 1);
    CMD(&body, CallList, 1);
    uint32_t id = resource(b, RGL_RES_COMMANDS, body.data, body.len);
    seq_init(&s);
    camera(&s);
    CMD(&s, NewList, 1, GL_COMPILE, id);
    CMD(&s, CallList, 1);
    frame(b, 0, &s);
    finish(b, true, dir, name);
    seq_free(&body);
    seq_free(&s);
    rgl_trace_builder_destroy(b);
}

/* A list that uploads a 256 x 256 luminance texture (64 KiB in the trace,
 * 256 KiB as RGBA), draws a textured triangle and calls itself twice. */
static void texture_bomb(const char *dir)
{
    rgl_trace_builder *b = rgl_trace_builder_create();
    static uint8_t lum[256 * 256];
    for (size_t i = 0; i < sizeof lum; i++)
        lum[i] = (uint8_t)(i * 13 + (i >> 8));
    uint32_t px = resource(b, RGL_RES_BYTES, lum, sizeof lum);
    seq body, s;
    seq_init(&body);
    CMD(&body, TexImage2D, GL_TEXTURE_2D, 0, GL_LUMINANCE, 256, 256, 0, GL_LUMINANCE,
        GL_UNSIGNED_BYTE, px);
    CMD(&body, Begin, GL_TRIANGLES);
    CMD(&body, TexCoord2f, 0, 0);
    CMD(&body, Vertex3f, 0, 0, -1);
    CMD(&body, TexCoord2f, 1, 0);
    CMD(&body, Vertex3f, 1, 0, -1);
    CMD(&body, TexCoord2f, 0, 1);
    CMD(&body, Vertex3f, 0, 1, -1);
    CMD0(&body, End);
    CMD(&body, CallList, 1);
    CMD(&body, CallList, 1);
    uint32_t id = resource(b, RGL_RES_COMMANDS, body.data, body.len);
    seq_init(&s);
    camera(&s);
    CMD(&s, BindTexture, GL_TEXTURE_2D, 1);
    CMD(&s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    CMD(&s, Enable, GL_TEXTURE_2D);
    CMD(&s, NewList, 1, GL_COMPILE, id);
    CMD(&s, CallList, 1);
    frame(b, 0, &s);
    finish(b, true, dir, "bomb-texture.raygl");
    seq_free(&body);
    seq_free(&s);
    rgl_trace_builder_destroy(b);
}

static void chain(rgl_trace_builder *b, seq *s, uint32_t first, int depth, const seq *body);

/* A list whose every call draws a textured triangle at another r of a
 * 64 x 64 x 64 3D texture (the texture matrix moves on at each call): a
 * new slice image at every draw, each counted, however the lists share. */
static void slice_bomb(const char *dir)
{
    rgl_trace_builder *b = rgl_trace_builder_create();
    static uint8_t lum[64 * 64 * 64];
    for (size_t i = 0; i < sizeof lum; i++)
        lum[i] = (uint8_t)(i * 29 + (i >> 12));
    uint32_t px = resource(b, RGL_RES_BYTES, lum, sizeof lum);
    seq body, s;
    seq_init(&body);
    CMD(&body, MatrixMode, GL_TEXTURE);
    CMD(&body, Translatef, 0, 0, 1.0 / 4096);
    CMD(&body, MatrixMode, GL_MODELVIEW);
    CMD(&body, Begin, GL_TRIANGLES);
    CMD(&body, TexCoord3f, 0, 0, 0.5);
    CMD(&body, Vertex3f, 0, 0, -1);
    CMD(&body, TexCoord3f, 1, 0, 0.5);
    CMD(&body, Vertex3f, 1, 0, -1);
    CMD(&body, TexCoord3f, 0, 1, 0.5);
    CMD(&body, Vertex3f, 0, 1, -1);
    CMD0(&body, End);
    CMD(&body, CallList, 1);
    CMD(&body, CallList, 1);
    uint32_t id = resource(b, RGL_RES_COMMANDS, body.data, body.len);
    seq_init(&s);
    camera(&s);
    CMD(&s, BindTexture, GL_TEXTURE_3D, 1);
    CMD(&s, TexParameteri, GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    CMD(&s, TexParameteri, GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    CMD(&s, TexImage3D, GL_TEXTURE_3D, 0, GL_LUMINANCE, 64, 64, 64, 0, GL_LUMINANCE,
        GL_UNSIGNED_BYTE, px);
    CMD(&s, Enable, GL_TEXTURE_3D);
    CMD(&s, NewList, 1, GL_COMPILE, id);
    CMD(&s, CallList, 1);
    frame(b, 0, &s);
    finish(b, true, dir, "bomb-slices.raygl");
    seq_free(&body);
    seq_free(&s);
    rgl_trace_builder_destroy(b);
}

/* The honest counterpart: one 256 x 256 texture, mipmapped by
 * gluBuild2DMipmaps, drawn by 10240 triangles (a list of 10 called 1024
 * times through a doubling chain): counted once, never cut (issue 22). */
static void honest_texture(const char *dir)
{
    rgl_trace_builder *b = rgl_trace_builder_create();
    static uint8_t lum[256 * 256];
    for (size_t i = 0; i < sizeof lum; i++)
        lum[i] = (uint8_t)(i * 13 + (i >> 8));
    uint32_t px = resource(b, RGL_RES_BYTES, lum, sizeof lum);
    seq body, s;
    seq_init(&body);
    for (int k = 0; k < 10; k++) {
        CMD(&body, Begin, GL_TRIANGLES);
        CMD(&body, TexCoord2f, 0, 0);
        CMD(&body, Vertex3f, 0, 0, -1);
        CMD(&body, TexCoord2f, 1, 0);
        CMD(&body, Vertex3f, 1, 0, -1);
        CMD(&body, TexCoord2f, 0, 1);
        CMD(&body, Vertex3f, 0, 1, -1);
        CMD0(&body, End);
        CMD(&body, Translatef, 1e-3, 0, 0);
    }
    seq_init(&s);
    camera(&s);
    CMD(&s, BindTexture, GL_TEXTURE_2D, 1);
    CMD(&s, Build2DMipmaps, GL_TEXTURE_2D, GL_LUMINANCE, 256, 256, GL_LUMINANCE, GL_UNSIGNED_BYTE,
        px);
    CMD(&s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    CMD(&s, Enable, GL_TEXTURE_2D);
    chain(b, &s, 10, 10, &body);
    CMD(&s, CallList, 10);
    frame(b, 0, &s);
    finish(b, true, dir, "honest-texture.raygl");
    seq_free(&body);
    seq_free(&s);
    rgl_trace_builder_destroy(b);
}

/* 50000 texture objects and 50000 lists, named in decreasing order, then a
 * list that binds a texture and deletes a range of lists 1000 times and
 * calls itself twice: every lookup must cost the same whatever the table. */
static void names_bomb(const char *dir)
{
    rgl_trace_builder *b = rgl_trace_builder_create();
    seq body, s;
    seq_init(&body);
    for (int i = 0; i < 1000; i++) {
        CMD(&body, BindTexture, GL_TEXTURE_2D, 7);
        CMD(&body, DeleteLists, 60000, 1000);
    }
    CMD(&body, CallList, 1);
    CMD(&body, CallList, 1);
    uint32_t id = resource(b, RGL_RES_COMMANDS, body.data, body.len);
    seq_init(&s);
    camera(&s);
    for (int i = 50000; i > 0; i--) {
        CMD(&s, BindTexture, GL_TEXTURE_2D, 10 + i);
        CMD(&s, NewList, 10 + i, GL_COMPILE, 0);
    }
    CMD(&s, NewList, 1, GL_COMPILE, id);
    CMD(&s, CallList, 1);
    frame(b, 0, &s);
    finish(b, true, dir, "bomb-names.raygl");
    seq_free(&body);
    seq_free(&s);
    rgl_trace_builder_destroy(b);
}

/* Frame 0 uploads texture 1 and draws with it; frame 1 carries it and
 * draws with it again. The pixels' span is printed as "tex-pixels START
 * END". */
static void texture_frames(const char *dir)
{
    rgl_trace_builder *b = rgl_trace_builder_create();
    uint8_t lum[64];
    for (size_t i = 0; i < sizeof lum; i++)
        lum[i] = (uint8_t)(i * 37 + 11);
    uint32_t px = resource(b, RGL_RES_BYTES, lum, sizeof lum);
    for (uint32_t f = 0; f < 2; f++) {
        seq s;
        seq_init(&s);
        if (f == 0) {
            camera(&s);
            CMD(&s, BindTexture, GL_TEXTURE_2D, 1);
            CMD(&s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_LUMINANCE, 8, 8, 0, GL_LUMINANCE,
                GL_UNSIGNED_BYTE, px);
            CMD(&s, Enable, GL_TEXTURE_2D);
        }
        CMD(&s, Begin, GL_TRIANGLES);
        CMD(&s, TexCoord2f, 0, 0);
        CMD(&s, Vertex3f, 0, 0, -1);
        CMD(&s, TexCoord2f, 1, 0);
        CMD(&s, Vertex3f, 1, 0, -1);
        CMD(&s, TexCoord2f, 0, 1);
        CMD(&s, Vertex3f, 0, 1, -1);
        CMD0(&s, End);
        if (rgl_trace_builder_frame(b, 0, f, f ? RGL_FRAME_STATE_CARRIED : 0, 0, s.data, s.len) !=
            RGL_OK)
            exit(1);
        seq_free(&s);
    }
    const uint8_t *data;
    size_t size;
    if (rgl_trace_builder_finish(b, true, &data, &size) != RGL_OK)
        exit(1);
    char path[4096];
    snprintf(path, sizeof path, "%s/texframes.raygl", dir);
    write_file(path, data, size);
    for (size_t i = 0; i + sizeof lum <= size; i++)
        if (memcmp(data + i, lum, sizeof lum) == 0)
            printf("tex-pixels %zu %zu\n", i, i + sizeof lum);
    rgl_trace_builder_destroy(b);
}

/* Lists first .. first + depth: each calls the next twice, the last runs
 * body: 2^depth runs of it from one call of `first`. */
static void chain(rgl_trace_builder *b, seq *s, uint32_t first, int depth, const seq *body)
{
    uint32_t leaf = resource(b, RGL_RES_COMMANDS, body->data, body->len);
    CMD(s, NewList, first + (uint32_t)depth, GL_COMPILE, leaf);
    for (int k = depth - 1; k >= 0; k--) {
        seq inner;
        seq_init(&inner);
        CMD(&inner, CallList, first + (uint32_t)k + 1);
        CMD(&inner, CallList, first + (uint32_t)k + 1);
        CMD(s, NewList, first + (uint32_t)k, GL_COMPILE,
            resource(b, RGL_RES_COMMANDS, inner.data, inner.len));
        seq_free(&inner);
    }
}

/* Every budget filled to just under its bound in one frame, by doubling
 * chains that stop short of a cut: 3.9 M vertices in triangles, 983 k
 * lines, 262 k solids (the worst case for memory a trace can ask for). */
static void fill_all(const char *dir)
{
    rgl_trace_builder *b = rgl_trace_builder_create();
    seq s, body;
    seq_init(&s);
    camera(&s);
    for (int kind = 0; kind < 3; kind++) {
        seq_init(&body);
        if (kind < 2) {
            CMD(&body, Begin, kind == 0 ? GL_TRIANGLES : GL_LINES);
            for (int i = 0; i < 30; i++)
                CMD(&body, Vertex3f, i % 3 == 1, i % 3 == 2, -(double)i / 30);
            CMD0(&body, End);
        } else {
            CMD(&body, SolidSphere, 0.5, 8, 8);
        }
        CMD(&body, Translatef, 1e-3, 0, 0);
        uint32_t first = 100u * (uint32_t)(kind + 1);
        chain(b, &s, first, kind == 0 ? 17 : kind == 1 ? 16 : 18, &body);
        CMD(&s, CallList, first);
        seq_free(&body);
    }
    frame(b, 0, &s);
    frame(b, 1, &s);
    finish(b, true, dir, "fill-all.raygl");
    seq_free(&s);
    rgl_trace_builder_destroy(b);
}

static void heavy_redo(const char *dir)
{
    rgl_trace_builder *b = rgl_trace_builder_create();
    seq s, body;
    seq_init(&s);
    CMD(&s, Viewport, 0, 0, 64, 48);
    CMD(&s, Enable, GL_DEPTH_TEST);
    CMD(&s, MatrixMode, GL_PROJECTION);
    CMD(&s, Ortho, -1, 1, -1, 1, -1, 1);
    CMD(&s, MatrixMode, GL_MODELVIEW);
    CMD(&s, Begin, GL_QUADS);
    CMD(&s, Vertex3f, -1, -1, 0.9);
    CMD(&s, Vertex3f, 1, -1, 0.9);
    CMD(&s, Vertex3f, 1, 1, 0.9);
    CMD(&s, Vertex3f, -1, 1, 0.9);
    CMD0(&s, End);
    CMD(&s, MatrixMode, GL_PROJECTION);
    CMD0(&s, LoadIdentity);
    CMD(&s, Frustum, -1, 1, -0.75, 0.75, 1, 100);
    CMD(&s, MatrixMode, GL_MODELVIEW);
    CMD(&s, Translatef, 0, 0, -5);
    seq_init(&body);
    CMD(&body, Begin, GL_TRIANGLES);
    for (int i = 0; i < 30; i++)
        CMD(&body, Vertex3f, i % 3 == 1, i % 3 == 2, -(double)i / 30);
    CMD0(&body, End);
    CMD(&body, Translatef, 1e-3, 0, 0);
    chain(b, &s, 100, 14, &body);
    CMD(&s, CallList, 100);
    frame(b, 0, &s);
    finish(b, true, dir, "heavy-redo.raygl");
    seq_free(&body);
    seq_free(&s);
    rgl_trace_builder_destroy(b);
}

/* ncalls outermost calls of a list of nverts vertices, each shared. */
static void many_calls(const char *dir, const char *name, int nverts, int ncalls)
{
    rgl_trace_builder *b = rgl_trace_builder_create();
    seq body, s;
    seq_init(&body);
    CMD(&body, Begin, GL_TRIANGLES);
    for (int i = 0; i < nverts; i++)
        CMD(&body, Vertex3f, (i % 3 == 1) * 0.01, (i % 3 == 2) * 0.01, -(double)i / nverts);
    CMD0(&body, End);
    uint32_t id = resource(b, RGL_RES_COMMANDS, body.data, body.len);
    seq_init(&s);
    camera(&s);
    CMD(&s, NewList, 1, GL_COMPILE, id);
    for (int i = 0; i < ncalls; i++) {
        CMD(&s, Translatef, 1e-5, 0, 0);
        CMD(&s, CallList, 1);
    }
    frame(b, 0, &s);
    finish(b, true, dir, name);
    seq_free(&body);
    seq_free(&s);
    rgl_trace_builder_destroy(b);
}

static void lists(const char *dir)
{
    rgl_trace_builder *b = rgl_trace_builder_create();
    seq tri, outer, s;
    seq_init(&tri);
    CMD(&tri, Begin, GL_TRIANGLES);
    CMD(&tri, Vertex2f, 0, 0);
    CMD(&tri, Vertex2f, 1, 0);
    CMD(&tri, Vertex2f, 0, 1);
    CMD0(&tri, End);
    uint32_t t = resource(b, RGL_RES_COMMANDS, tri.data, tri.len);
    seq_init(&outer);
    CMD(&outer, Translatef, 1, 0, 0);
    CMD(&outer, CallList, 1);
    uint32_t o = resource(b, RGL_RES_COMMANDS, outer.data, outer.len);
    /* Frame 1 carries frame 0's state: its camera and lists. */
    seq_init(&s);
    camera(&s);
    CMD(&s, NewList, 1, GL_COMPILE, t);
    CMD(&s, NewList, 2, GL_COMPILE, o);
    CMD(&s, CallList, 1);
    CMD(&s, CallList, 2);
    frame(b, 0, &s);
    seq f0 = s;
    seq_init(&s);
    CMD(&s, CallList, 2);
    if (rgl_trace_builder_frame(b, 0, 1, RGL_FRAME_STATE_CARRIED, 0, s.data, s.len) != RGL_OK)
        exit(1);
    seq_free(&s);
    const uint8_t *data;
    size_t size;
    if (rgl_trace_builder_finish(b, true, &data, &size) != RGL_OK)
        exit(1);
    char path[4096];
    snprintf(path, sizeof path, "%s/lists.raygl", dir);
    write_file(path, data, size);
    for (size_t i = 0; i + tri.len <= size; i++)
        if (memcmp(data + i, tri.data, tri.len) == 0)
            printf("list-body %zu %zu\n", i, i + tri.len);
    for (size_t i = 0; i + f0.len <= size; i++)
        if (memcmp(data + i, f0.data, f0.len) == 0)
            printf("frame-0 %zu %zu\n", i, i + f0.len);
    seq_free(&f0);
    seq_free(&tri);
    seq_free(&outer);
    rgl_trace_builder_destroy(b);
}

static void unclosed(const char *dir, bool cut)
{
    rgl_trace_builder *b = rgl_trace_builder_create();
    seq s;
    for (uint32_t f = 0; f < (cut ? 4u : 3u); f++) {
        seq_init(&s);
        camera(&s);
        CMD(&s, Begin, GL_TRIANGLES);
        CMD(&s, Vertex2f, 0, 0);
        CMD(&s, Vertex2f, 1, 0);
        CMD(&s, Vertex2f, 0, 1);
        CMD0(&s, End);
        frame(b, f, &s);
        seq_free(&s);
    }
    const uint8_t *data;
    size_t size;
    if (rgl_trace_builder_finish(b, false, &data, &size) != RGL_OK)
        exit(1);
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, cut ? "cut.raygl" : "unclosed.raygl");
    write_file(path, data, cut ? size - 20 : size); /* 20: inside the last frame */
    rgl_trace_builder_destroy(b);
}

/* An image resource of the snapshot: any bytes do for raygl2pov; a real
 * zlib stream is not needed to show that translation never reads it. */
static void snapshots(const char *dir)
{
    rgl_trace_builder *b = rgl_trace_builder_create();
    uint8_t image[64];
    for (size_t i = 0; i < sizeof image; i++)
        image[i] = (uint8_t)(i * 7);
    uint32_t img = resource(b, RGL_RES_BYTES, image, sizeof image);
    for (uint32_t f = 0; f < 3; f++) {
        seq s;
        seq_init(&s);
        camera(&s);
        CMD(&s, Begin, GL_TRIANGLES);
        CMD(&s, Vertex2f, 0, 0);
        CMD(&s, Vertex2f, 1, 0);
        CMD(&s, Vertex2f, 0, 1);
        CMD0(&s, End);
        CMD(&s, Snapshot, 0, 0, 4, 4, 0x1907, 1, img);
        frame(b, f, &s);
        seq_free(&s);
    }
    const uint8_t *data;
    size_t size;
    if (rgl_trace_builder_finish(b, true, &data, &size) != RGL_OK)
        exit(1);
    char path[4096];
    snprintf(path, sizeof path, "%s/snap.raygl", dir);
    write_file(path, data, size);
    const uint8_t *hit = NULL;
    for (size_t i = 0; i + sizeof image <= size; i++)
        if (memcmp(data + i, image, sizeof image) == 0)
            hit = data + i;
    if (hit)
        printf("snapshot-image %zu %zu\n", (size_t)(hit - data), (size_t)(hit - data) + sizeof image);
    rgl_trace_builder_destroy(b);
}

/* Four 8 x 6 frames with real snapshots: frame 0 its own image, frames
 * 1-3 one shared image (the recorder shares an unchanged picture); that
 * shared image's span is printed as "shared-image START END". */
static void *grow(void *p, size_t n) { return realloc(p, n); }

static void compare_snapshots(const char *dir)
{
    rgl_trace_builder *b = rgl_trace_builder_create();
    uint32_t img[2];
    size_t at[2] = {0, 0}, len[2] = {0, 0};
    uint8_t *z[2];
    for (int k = 0; k < 2; k++) {
        uint8_t rgb[8 * 6 * 3];
        for (size_t i = 0; i < sizeof rgb; i++)
            rgb[i] = (uint8_t)(k ? 0x40 : 0x20); /* background: the clear colour */
        if (rgl_snapshot_encode(rgb, 8, 6, 9, grow, &z[k], &len[k]) != RGL_OK)
            exit(1);
        img[k] = resource(b, RGL_RES_BYTES, z[k], len[k]);
    }
    for (uint32_t f = 0; f < 4; f++) {
        seq s;
        seq_init(&s);
        CMD(&s, Viewport, 0, 0, 8, 6);
        double c = f ? 0x40 / 255.0 : 0x20 / 255.0;
        CMD(&s, ClearColor, c, c, c, 1);
        CMD(&s, Clear, GL_COLOR_BUFFER_BIT);
        CMD(&s, Snapshot, 0, 0, 8, 6, 0x1907, 1, img[f ? 1 : 0]);
        frame(b, f, &s);
        seq_free(&s);
    }
    const uint8_t *data;
    size_t size;
    if (rgl_trace_builder_finish(b, true, &data, &size) != RGL_OK)
        exit(1);
    char path[4096];
    snprintf(path, sizeof path, "%s/snapshots.raygl", dir);
    write_file(path, data, size);
    for (size_t i = 0; i + len[1] <= size; i++)
        if (memcmp(data + i, z[1], len[1]) == 0)
            at[1] = i;
    printf("shared-image %zu %zu\n", at[1], at[1] + len[1]);
    free(z[0]);
    free(z[1]);
    rgl_trace_builder_destroy(b);
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: mkhostile DIR\n");
        return 2;
    }
    const char *dir = argv[1];
    bomb(dir, "bomb-3.raygl", 0, 3);
    bomb(dir, "bomb-30.raygl", 0, 30);
    bomb(dir, "bomb-300.raygl", 0, 300);
    bomb(dir, "bomb-solid.raygl", 1, 0);
    bomb(dir, "bomb-empty.raygl", 2, 4000);
    bomb(dir, "bomb-lines.raygl", 3, 30);
    texture_bomb(dir);
    slice_bomb(dir);
    honest_texture(dir);
    names_bomb(dir);
    texture_frames(dir);
    fill_all(dir);
    heavy_redo(dir);
    many_calls(dir, "bomb-calls.raygl", 3, 100000);
    many_calls(dir, "bomb-calls300.raygl", 300, 60000);
    lists(dir);
    unclosed(dir, false);
    unclosed(dir, true);
    snapshots(dir);
    compare_snapshots(dir);
    return 0;
}
