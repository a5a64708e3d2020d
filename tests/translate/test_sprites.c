/* test_sprites.c: textured points and point sprites (interp_sprite.c).
 *
 * A textured point becomes a textured square (the sample at its vertex's
 * coordinates, or with GL_COORD_REPLACE under GL_POINT_SPRITE the square
 * spanning the texture, t down from GL_UPPER_LEFT or up from
 * GL_LOWER_LEFT); an incomplete texture leaves the point as it is; a
 * smooth textured point without sprites and a textured line are noted.
 */
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "interp_fixture.h"
#include "interp.h"
#include "tracegen.h"

static const uint8_t px[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};

static void setup(seq *s, uint32_t id, bool complete)
{
    CMD(s, Viewport, 0, 0, 100, 100);
    CMD(s, MatrixMode, GL_PROJECTION);
    CMD(s, Ortho, 0, 100, 0, 100, -1, 1);
    CMD(s, MatrixMode, GL_MODELVIEW);
    CMD(s, BindTexture, GL_TEXTURE_2D, 1);
    if (complete) {
        CMD(s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        CMD(s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    CMD(s, TexImage2D, GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, id);
    CMD(s, Enable, GL_TEXTURE_2D);
    CMD(s, PointSize, 10);
}

static void point(seq *s)
{
    CMD(s, Begin, GL_POINTS);
    CMD(s, TexCoord2f, 0.25, 0.75);
    CMD(s, Vertex2f, 50.5, 50.5);
    CMD0(s, End);
}

/* The texture coordinates of the last mesh's corners. */
static bool corners(float uv[4][2])
{
    if (sc.nmeshes == 0 || sc.meshes[sc.nmeshes - 1].tri_count != 2)
        return false;
    const scene_mesh *m = &sc.meshes[sc.nmeshes - 1];
    const scene_tri *t = &sc.tris[m->first_tri];
    uint32_t v[4] = {t[0].v[0], t[0].v[1], t[0].v[2], t[1].v[2]};
    for (int k = 0; k < 4; k++)
        memcpy(uv[k], sc.verts[v[k]].tex, sizeof uv[k]);
    return m->in_eye && m->look.texture >= 0 && !m->look.lit;
}

static void test_sprites(void)
{
    uint32_t id = add_bytes(px, sizeof px);
    /* 0: a sprite, upper-left origin; 1: lower-left; 2: a textured point */
    for (int c = 0; c < 3; c++) {
        interp *ip = fresh();
        seq s;
        seq_init(&s);
        setup(&s, id, true);
        if (c < 2) {
            CMD(&s, Enable, GL_POINT_SPRITE);
            CMD(&s, TexEnvi, GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
        }
        if (c == 1)
            CMD(&s, PointParameteri, GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
        point(&s);
        run(ip, &s);
        float uv[4][2];
        CHECK(corners(uv));
        CHECK_EQ_U(sc.npoints, 0);
        CHECK_EQ_U(count(DIAG_NOTE_POINT_TEXTURE) + count(DIAG_NOTE_TEX_LINES), 0);
        if (corners(uv) && c < 2) { /* corners: lower left, lower right, upper right, upper left */
            CHECK(uv[0][0] == 0 && uv[1][0] == 1 && uv[2][0] == 1 && uv[3][0] == 0);
            CHECK(uv[0][1] == (c == 0 ? 1 : 0) && uv[2][1] == (c == 0 ? 0 : 1));
        }
        if (corners(uv) && c == 2)
            for (int k = 0; k < 4; k++)
                CHECK(uv[k][0] == 0.25f && uv[k][1] == 0.75f);
        interp_destroy(ip);
    }
    free_res();
}

static void test_untextured(void)
{
    uint32_t id = add_bytes(px, sizeof px);
    /* 0: incomplete texture (mipmapped filter, no levels): the point stays;
     * 1: smooth, no sprite: noted, the point stays; 2: a textured line, noted */
    for (int c = 0; c < 3; c++) {
        interp *ip = fresh();
        seq s;
        seq_init(&s);
        setup(&s, id, c != 0);
        if (c == 1)
            CMD(&s, Enable, GL_POINT_SMOOTH);
        if (c < 2) {
            point(&s);
        } else {
            CMD(&s, Begin, GL_LINES);
            CMD(&s, Vertex2f, 10.5, 10.5);
            CMD(&s, Vertex2f, 80.5, 20.5);
            CMD0(&s, End);
        }
        run(ip, &s);
        /* a square point is one, a round one a rectangle per run of rows */
        CHECK(c == 0 ? sc.npoints == 1 : c == 1 ? sc.npoints > 1 : sc.npoints == 0);
        CHECK_EQ_U(count(DIAG_NOTE_POINT_TEXTURE), c == 1);
        CHECK_EQ_U(count(DIAG_NOTE_TEX_LINES), c == 2);
        interp_destroy(ip);
    }
    free_res();
}

int main(void)
{
    scene_init(&sc);
    fx_fetch = fetch_res;
    test_sprites();
    test_untextured();
    scene_finish(&sc);
    return CHECK_RESULT("test_sprites");
}
