/* mtex_arrays.c: the multitexture quad from vertex arrays: unit 0's and
 * unit 1's coordinates in arrays of their own client units
 * (glClientActiveTexture + glTexCoordPointer), unit 1's in doubles, drawn
 * with glDrawArrays while unit 1 is the client active unit (mtex_scene.h). */
#include "harness.h"
#include "mtex_scene.h"

static int draw(int w, int h)
{
    tex_view(w, h);
    mtex_make(GL_MODULATE, GL_MODULATE);
    static const float col[4][3] = {{1, 1, 1}, {1, 0.5f, 0.5f}, {0.5f, 1, 0.6f}, {0.6f, 0.6f, 1}};
    double st1[4][2];
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 2; k++)
            st1[i][k] = mtex_st1[i][k];
    rayglVertexPointer(2, GL_FLOAT, 0, mtex_pos);
    rayglColorPointer(3, GL_FLOAT, 0, col);
    rayglEnableClientState(GL_VERTEX_ARRAY);
    rayglEnableClientState(GL_COLOR_ARRAY);
    rayglClientActiveTexture(GL_TEXTURE0);
    rayglTexCoordPointer(2, GL_FLOAT, 0, mtex_st0);
    rayglEnableClientState(GL_TEXTURE_COORD_ARRAY);
    rayglClientActiveTextureARB(GL_TEXTURE1);
    rayglTexCoordPointer(2, GL_DOUBLE, 0, st1);
    rayglEnableClientState(GL_TEXTURE_COORD_ARRAY);
    rayglDrawArrays(GL_QUADS, 0, 4);
    return 0;
}

RGL_TEST_MAIN(draw)
