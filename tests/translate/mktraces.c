/* mktraces.c: writes the traces test_cli.sh uses into a folder.
 *
 *   mktraces DIR
 *
 * DIR/good.raygl   ten frames over two streams: the golden scenes, a frame
 *                  with a state snapshot, a STATE_CARRIED frame that draws
 *                  with the state its stream's first frame set, and
 *                  rayglFrameBegin frames with hostile names ("../../x.pov",
 *                  "/etc/passwd", "a b;c.pov", a name used twice, "").
 * DIR/big.raygl    one frame of 20000 triangles (for the full-disk test).
 *
 *   mktraces --seeds DIR
 *
 * writes the fuzz target's seed corpus (tests/translate/fuzz/corpus): each
 * test scene as a whole trace, and as a bare command sequence behind the
 * target's flag byte.
 */
#include <GL/gl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scenes.h"

static void seeds(const char *dir)
{
    void (*const builders[])(seq *) = {scene_paper_box, scene_smooth, scene_lines_points,
                                       scene_faces, scene_awkward};
    static const char *const names[] = {"paper_box", "smooth", "lines_points", "faces",
                                        "awkward"};
    static const unsigned char flags[] = {0, 5, 2, 8};
    char path[4096];
    for (size_t i = 0; i < sizeof builders / sizeof builders[0]; i++) {
        seq s;
        seq_init(&s);
        builders[i](&s);
        trace t;
        trace_init(&t);
        trace_frame(&t, 0, 0, 0, 0, &s);
        trace_frame(&t, 0, 1, RGL_FRAME_STATE_CARRIED, 0, &s);
        trace_finish(&t);
        snprintf(path, sizeof path, "%s/trace-%s", dir, names[i]);
        write_file(path, t.data, t.size);
        trace_free(&t);
        unsigned char *buf = malloc(s.len + 1);
        memcpy(buf + 1, s.data, s.len);
        buf[0] = flags[i % 4];
        snprintf(path, sizeof path, "%s/seq-%s", dir, names[i]);
        write_file(path, buf, s.len + 1);
        free(buf);
        seq_free(&s);
    }
    seq s;
    seq_init(&s);
    scene_framebegin(&s, "../name.pov");
    unsigned char *buf = malloc(s.len + 1);
    memcpy(buf + 1, s.data, s.len);
    buf[0] = 0;
    snprintf(path, sizeof path, "%s/seq-framebegin", dir);
    write_file(path, buf, s.len + 1);
    free(buf);
    seq_free(&s);
}

int main(int argc, char **argv)
{
    if (argc == 3 && strcmp(argv[1], "--seeds") == 0) {
        seeds(argv[2]);
        return 0;
    }
    if (argc != 2) {
        fprintf(stderr, "usage: mktraces DIR | mktraces --seeds DIR\n");
        return 2;
    }
    char path[4096];
    trace t;
    seq s;
    uint32_t n0 = 0, n1 = 0;

    trace_init(&t);
    seq_init(&s);
    scene_smooth(&s); /* frame 0, stream 0: sets the projection the carried frame uses */
    trace_frame(&t, 0, n0++, 0, 0, &s);
    seq_free(&s);
    seq_init(&s);
    scene_lines_points(&s); /* frame 1, stream 1 */
    trace_frame(&t, 1, n1++, 0, 0, &s);
    seq_free(&s);

    /* Frame 2, stream 0: carried state; only draws. */
    seq_init(&s);
    CMD(&s, Clear, GL_COLOR_BUFFER_BIT);
    CMD(&s, Begin, GL_TRIANGLES);
    CMD(&s, Color3f, 1, 0.5, 0);
    CMD(&s, Vertex3f, -1, -1, 0);
    CMD(&s, Vertex3f, 1, -1, 0);
    CMD(&s, Vertex3f, 0, 1, 0);
    CMD0(&s, End);
    trace_frame(&t, 0, n0++, RGL_FRAME_STATE_CARRIED, 0, &s);
    seq_free(&s);

    /* Frame 3, stream 1: a snapshot sets the state. */
    seq snap;
    seq_init(&snap);
    CMD(&snap, Viewport, 0, 0, 64, 48);
    CMD(&snap, MatrixMode, GL_PROJECTION);
    CMD(&snap, Matrix, GL_PROJECTION, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1);
    CMD(&snap, MatrixMode, GL_MODELVIEW);
    CMD(&snap, ClearColor, 0.5, 0, 0, 1);
    uint32_t id = trace_snapshot(&t, &snap);
    seq_free(&snap);
    seq_init(&s);
    CMD(&s, Clear, GL_COLOR_BUFFER_BIT);
    CMD(&s, Color3f, 0, 1, 0);
    CMD(&s, Rectf, -0.5, -0.5, 0.5, 0.5);
    trace_frame(&t, 1, n1++, RGL_FRAME_LIVE_CONTEXT, id, &s);
    seq_free(&s);

    seq_init(&s);
    scene_faces(&s); /* frame 4 */
    trace_frame(&t, 1, n1++, 0, 0, &s);
    seq_free(&s);

    const char *names[5] = {"../../x.pov", "/etc/passwd", "a b;c.pov", "../../x.pov", ""};
    for (int i = 0; i < 5; i++) { /* frames 5..9 */
        seq_init(&s);
        scene_framebegin(&s, names[i]);
        trace_frame(&t, 1, n1++, 0, 0, &s);
        seq_free(&s);
    }
    trace_finish(&t);
    snprintf(path, sizeof path, "%s/good.raygl", argv[1]);
    write_file(path, t.data, t.size);
    trace_free(&t);

    trace_init(&t);
    seq_init(&s);
    CMD(&s, Viewport, 0, 0, 100, 100);
    CMD(&s, Begin, GL_TRIANGLES);
    for (int i = 0; i < 20000; i++) {
        CMD(&s, Color3f, (i % 7) / 7.0, (i % 11) / 11.0, 0.5);
        CMD(&s, Vertex3f, (i % 100) / 100.0, (i / 100) / 200.0, 0);
        CMD(&s, Vertex3f, (i % 100) / 100.0 + 0.01, (i / 100) / 200.0, 0);
        CMD(&s, Vertex3f, (i % 100) / 100.0, (i / 100) / 200.0 + 0.005, 0);
    }
    CMD0(&s, End);
    trace_frame(&t, 0, 0, 0, 0, &s);
    trace_finish(&t);
    snprintf(path, sizeof path, "%s/big.raygl", argv[1]);
    write_file(path, t.data, t.size);
    seq_free(&s);
    trace_free(&t);

    /* @NotRecorded (format 1.3): frame 1 carries frame 0's state (replayed
     * without being reported again); a hostile name; a second stream; calls
     * that cannot change these frames (glutInit: never; glCompressedTexImage2D:
     * no draw is textured). */
    trace_init(&t);
    seq_init(&s);
    scene_smooth(&s);
    seq_cmd(&s, RGL_OP_NotRecorded, "glAccum", (const double[]){1000}, 1);
    seq_cmd(&s, RGL_OP_NotRecorded, "glRasterPos2i", (const double[]){1}, 1);
    seq_cmd(&s, RGL_OP_NotRecorded, "glutInit", (const double[]){1}, 1);
    seq_cmd(&s, RGL_OP_NotRecorded, "glCompressedTexImage2D", (const double[]){3}, 1);
    trace_frame(&t, 0, 0, 0, 0, &s);
    seq_free(&s);
    seq_init(&s);
    CMD(&s, Clear, GL_COLOR_BUFFER_BIT);
    seq_cmd(&s, RGL_OP_NotRecorded, "glMap1f", (const double[]){5}, 1);
    seq_cmd(&s, RGL_OP_NotRecorded, "glAccum", (const double[]){200}, 1);
    seq_cmd(&s, RGL_OP_NotRecorded, "glAccum", (const double[]){4}, 1);
    seq_cmd(&s, RGL_OP_NotRecorded, "gl\033[31mEvil\n", (const double[]){2}, 1);
    trace_frame(&t, 0, 1, RGL_FRAME_STATE_CARRIED, 0, &s);
    seq_free(&s);
    seq_init(&s);
    scene_lines_points(&s);
    seq_cmd(&s, RGL_OP_NotRecorded, "glutBitmapCharacter", (const double[]){7}, 1);
    seq_cmd(&s, RGL_OP_NotRecorded, "glActiveTexture", (const double[]){1}, 1);
    trace_frame(&t, 1, 0, 0, 0, &s);
    seq_free(&s);
    trace_finish(&t);
    snprintf(path, sizeof path, "%s/unrecorded.raygl", argv[1]);
    write_file(path, t.data, t.size);
    trace_free(&t);
    return 0;
}
