/* harness.h: the shared frame of the image-test programs.
 *
 * Each program in tests/programs/ draws one frame of a small GL scene with
 * the raygl* API (or the drop-in header). The harness gives it an OSMesa
 * context of the requested size, opens the trace, and after the drawing ends
 * the frame, reads the GL image back and writes it as a PNG. The image test
 * (tests/image/run-image-test.sh) then translates the trace with raygl2pov,
 * renders it with POV-Ray and compares the two PNGs.
 *
 * Command line of every program:
 *
 *     prog --trace out.raygl --png out-gl.png [--size WxH]
 *
 * The default size is 320x240. A program is written against the size it is
 * given (viewport, aspect), so the same scene can run at other sizes.
 *
 * The harness itself makes no raygl call besides opening, ending and closing
 * the recording: the frame holds exactly what the program drew.
 */
#ifndef RGL_TEST_HARNESS_H
#define RGL_TEST_HARNESS_H

#include <GL/osmesa.h>

#include <GL/gl.h>
#include <GL/glu.h>

#define RGL_TEST_DEFAULT_WIDTH 320
#define RGL_TEST_DEFAULT_HEIGHT 240

typedef struct rgl_test {
    int width, height;      /* of the OSMesa buffer and of the PNG */
    const char *trace_path; /* --trace */
    const char *png_path;   /* --png */
    const char *name;       /* argv[0], for messages */
    OSMesaContext ctx;
    unsigned char *pixels; /* RGBA, width * height * 4, bottom row first */
} rgl_test;

/* Parses the command line, creates an OSMesa RGBA context with a 24-bit
 * depth buffer, an 8-bit stencil buffer and a 16-bit accumulation buffer,
 * makes it current on a
 * buffer of the requested size (filled with a sentinel pattern, so an image
 * GL never drew into is detected) and opens the trace with
 * rayglRecordOpen(). Returns 0, or the exit status the program should
 * return (2 bad usage, 1 failure) after printing why. */
int rgl_test_init(rgl_test *t, int argc, char **argv);

/* Ends the frame (rayglFrameEnd), waits for GL, reads the image, checks that
 * it came from OSMesa and shows something besides one flat colour, writes it
 * top row first as an 8-bit RGB PNG tagged gAMA 0.45455 (as POV-Ray tags
 * File_Gamma=2.2 output), closes the trace and the context. Returns the exit
 * status: 0 on success, 1 after printing what failed. */
int rgl_test_finish(rgl_test *t);

/* A main() for the common case: init, draw(width, height), finish. draw
 * returns 0, or 1 after printing why the scene could not be drawn as meant
 * (a program may check GL's own state, as the paper's example checks the
 * modelview matrix); the frame is finished either way. */
#define RGL_TEST_MAIN(draw)                               \
    int main(int argc, char **argv)                       \
    {                                                     \
        rgl_test t_;                                      \
        int rc_ = rgl_test_init(&t_, argc, argv);         \
        if (rc_ != 0)                                     \
            return rc_;                                   \
        int drc_ = draw(t_.width, t_.height);             \
        rc_ = rgl_test_finish(&t_);                       \
        return drc_ != 0 ? drc_ : rc_;                    \
    }

#endif
