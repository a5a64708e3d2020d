/* mktextrace.c: writes the trace test_texfiles.sh translates.
 *
 *   mktextrace FILE
 *
 * Four frames of one stream: frame 0 defines a 4 x 4 texture and draws two
 * textured triangles; frames 1 and 2 carry the state and draw again (the
 * same image); frame 3 patches the texture with glTexSubImage2D and draws
 * (a second image). So the folder must end up with exactly two images.
 */
#include <GL/gl.h>
#include <stdint.h>
#include <stdio.h>

#include "tracegen.h"

static void draw(seq *s)
{
    CMD(s, Clear, GL_COLOR_BUFFER_BIT);
    for (int k = 0; k < 2; k++) {
        CMD(s, Begin, GL_TRIANGLES);
        CMD(s, TexCoord2f, 0, 0);
        CMD(s, Vertex2f, -0.9 + k, -0.9);
        CMD(s, TexCoord2f, 1, 0);
        CMD(s, Vertex2f, -0.1 + k, -0.9);
        CMD(s, TexCoord2f, 0, 1);
        CMD(s, Vertex2f, -0.9 + k, 0.9);
        CMD0(s, End);
    }
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: mktextrace FILE\n");
        return 2;
    }
    uint8_t px[4 * 4 * 3];
    for (int i = 0; i < 48; i++)
        px[i] = (uint8_t)(i * 5);
    const uint8_t patch[3] = {255, 0, 255};
    trace t;
    trace_init(&t);
    uint32_t idp, idq;
    if (rgl_trace_builder_resource(t.b, RGL_RES_BYTES, px, sizeof px, &idp) != RGL_OK ||
        rgl_trace_builder_resource(t.b, RGL_RES_BYTES, patch, sizeof patch, &idq) != RGL_OK)
        return 1;
    for (uint32_t f = 0; f < 4; f++) {
        seq s;
        seq_init(&s);
        if (f == 0) {
            CMD(&s, Viewport, 0, 0, 64, 48);
            CMD(&s, BindTexture, GL_TEXTURE_2D, 1);
            CMD(&s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, idp);
            CMD(&s, Enable, GL_TEXTURE_2D);
        }
        if (f == 3)
            CMD(&s, TexSubImage2D, GL_TEXTURE_2D, 0, 1, 1, 1, 1, GL_RGB, GL_UNSIGNED_BYTE, idq);
        draw(&s);
        trace_frame(&t, 0, f, f ? RGL_FRAME_STATE_CARRIED : 0, 0, &s);
        seq_free(&s);
    }
    trace_finish(&t);
    write_file(argv[1], t.data, t.size);
    trace_free(&t);
    return 0;
}
