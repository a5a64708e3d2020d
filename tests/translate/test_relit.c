/* test_relit.c: issue 14's differences that were silent (interp_relit.c,
 * interp_fogbehind.c): back faces under one-sided lighting and textured
 * GL_MODULATE surfaces lit past white take GL's own per-vertex colours in
 * an unlit mesh, other faces keep POV-Ray's lighting; a fogged primitive
 * reaching behind the eye is noted, an ordinary fogged one is not.
 */
#include <GL/gl.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "interp_fixture.h"
#include "interp.h"
#include "interp_internal.h"
#include "tracegen.h"

/* A fresh interpreter, depth-tested as the programs are (no draw-order note). */
static interp *fresh_depth(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Enable, GL_DEPTH_TEST);
    run(ip, &s);
    return ip;
}

static size_t notes(void)
{
    size_t n = 0;
    for (int k = DIAG_FIRST_NOTE; k < DIAG_COUNT; k++)
        n += dlog.e[k].count;
    return n;
}

/* A triangle in the z = -0.5 plane (identity projection), counter-clockwise
 * in window space unless cw. */
static void tri(seq *s, bool cw)
{
    CMD(s, Begin, GL_TRIANGLES);
    CMD(s, TexCoord2f, 0, 0);
    CMD(s, Vertex3f, 0, 0, -0.5);
    CMD(s, TexCoord2f, 1, 0);
    CMD(s, Vertex3f, cw ? 0 : 0.5, cw ? 0.5 : 0, -0.5);
    CMD(s, TexCoord2f, 0, 1);
    CMD(s, Vertex3f, cw ? 0.5 : 0, cw ? 0 : 0.5, -0.5);
    CMD0(s, End);
}

static void lit(seq *s)
{
    CMD(s, Enable, GL_LIGHTING);
    CMD(s, Enable, GL_LIGHT0);
    CMD(s, Normal3f, 0, 0, 1);
}

/* GL's default light and material with N.L = 1: 0.2 * 0.2 + 0.8. */
#define DEFAULT_LIT 0.84

/* case 0: a front face, lit by POV-Ray; 1: a back face, lit as GL does;
 * 2: the back face with two-sided lighting, lit as GL does too (the back
 * material, the normal turned away from the light: the ambient term
 * 0.2 * 0.2 alone); 3: the back face culled; 4: --vertex-lighting (all
 * GL's already). */
static void test_back_faces(void)
{
    for (int c = 0; c < 5; c++) {
        interp *ip = fresh_depth();
        interp_set_vertex_lighting(ip, c == 4);
        seq s;
        seq_init(&s);
        lit(&s);
        if (c == 2)
            CMD(&s, LightModeli, GL_LIGHT_MODEL_TWO_SIDE, 1);
        if (c == 3)
            CMD(&s, Enable, GL_CULL_FACE);
        tri(&s, c != 0);
        run(ip, &s);
        size_t want_tris = c == 3 ? 0 : 1;
        CHECK_EQ_U(sc.ntris, want_tris);
        if (c == 3 || sc.nmeshes < 1) {
            interp_destroy(ip);
            continue;
        }
        const scene_mesh *m = &sc.meshes[sc.nmeshes - 1];
        bool gl_lit = c == 1 || c == 2 || c == 4;
        CHECK_EQ_U(m->tri_count, 1);
        CHECK(m->look.lit == !gl_lit);
        if (gl_lit && sc.ntris == 1)
            CHECK_NEAR(sc.verts[sc.tris[0].v[0]].color[0], c == 2 ? 0.04 : DEFAULT_LIT, 1e-6);
        CHECK_EQ_U(notes(), 0);
        interp_destroy(ip);
    }
}

/* A strip of a front then a back face: the front one stays lit by
 * POV-Ray, the back one goes to a second mesh with GL's colours, on
 * copies of its own three corners (not of the strip's fourth vertex);
 * glFrontFace(GL_CW) swaps them. */
static void test_mixed_strip(void)
{
    for (int cw = 0; cw < 2; cw++) {
        interp *ip = fresh_depth();
        seq s;
        seq_init(&s);
        lit(&s);
        if (cw)
            CMD(&s, FrontFace, GL_CW);
        /* 0 1 2 counter-clockwise; 1 3 2 (the second, odd triangle) folds over */
        CMD(&s, Begin, GL_TRIANGLE_STRIP);
        CMD(&s, Vertex3f, 0, 0, -0.5);
        CMD(&s, Vertex3f, 0.5, 0, -0.5);
        CMD(&s, Vertex3f, 0, 0.5, -0.5);
        CMD(&s, Vertex3f, -0.5, 0.2, -0.5);
        CMD0(&s, End);
        run(ip, &s);
        CHECK_EQ_U(sc.ntris, 2);
        CHECK_EQ_U(sc.nmeshes, 2);
        CHECK_EQ_U(sc.nverts, 7);
        if (sc.nmeshes == 2 && sc.nverts == 7) {
            CHECK(sc.meshes[0].look.lit && sc.meshes[0].tri_count == 1);
            CHECK(!sc.meshes[1].look.lit && sc.meshes[1].tri_count == 1);
            const scene_tri *t = &sc.tris[sc.meshes[1].first_tri];
            CHECK(t->v[0] >= 4 && t->v[1] >= 4 && t->v[2] >= 4);
            CHECK(t->v[0] != t->v[1] && t->v[1] != t->v[2] && t->v[2] != t->v[0]);
            /* cw: the first triangle is the back one (vertices 0 1 2) */
            bool first_back = cw != 0;
            for (int k = 0; k < 3; k++) {
                uint32_t v = 0; /* the vertex copied: the one at the copy's place */
                while (v < 4 && memcmp(sc.verts[v].pos, sc.verts[t->v[k]].pos,
                                       sizeof sc.verts[v].pos) != 0)
                    v++;
                CHECK(first_back ? v <= 2 : v >= 1 && v <= 3);
            }
        }
        interp_destroy(ip);
    }
}

/* A textured GL_MODULATE face whose lit colour passes 1 (an emission of
 * 0.5 over the default light) takes GL's clamped colour, and so does an
 * untextured one; lit to at most 1 (no emission), or GL_REPLACE, POV-Ray
 * lights it; so it does with GL_SEPARATE_SPECULAR_COLOR and a highlight,
 * which GL adds after the texture, with a note. */
static void test_modulate_past_white(void)
{
    static uint8_t rgb[12] = {200, 150, 90, 200, 150, 90, 200, 150, 90, 200, 150, 90};
    free_res();
    add_bytes(rgb, sizeof rgb); /* the texels, id 1 */
    for (int c = 0; c < 5; c++) {
        interp *ip = fresh_depth();
        seq s;
        seq_init(&s);
        lit(&s);
        if (c == 4) {
            CMD(&s, LightModeli, GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
            CMD(&s, Materialfv, GL_FRONT, GL_SPECULAR, 0.5, 0.5, 0.5, 1);
        }
        if (c != 1)
            CMD(&s, Materialfv, GL_FRONT, GL_EMISSION, 0.5, 0.5, 0.5, 1);
        if (c != 3) {
            CMD(&s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_RGB, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, 1);
            CMD(&s, Enable, GL_TEXTURE_2D);
            CMD(&s, TexEnvi, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, c == 2 ? GL_REPLACE : GL_MODULATE);
        }
        tri(&s, false);
        run(ip, &s);
        CHECK_EQ_U(sc.ntris, 1);
        if (sc.nmeshes >= 1 && sc.ntris == 1) {
            const scene_mesh *m = &sc.meshes[sc.nmeshes - 1];
            CHECK(m->look.lit == (c != 0 && c != 3));
            if (c == 0) {
                CHECK(m->look.texture >= 0);
                CHECK_NEAR(sc.verts[sc.tris[0].v[0]].color[0], 1, 1e-6); /* 1.34 clamped */
            }
        }
        CHECK_EQ_U(count(DIAG_GL_INVALID_VALUE) + count(DIAG_IGNORED), 0);
        CHECK_EQ_U(count(DIAG_NOTE_RELIT_SPECULAR), c == 4 ? 1 : 0);
        interp_destroy(ip);
    }
}

/* Under GL_SEPARATE_SPECULAR_COLOR with a highlight, a textured back face
 * stays lit by POV-Ray with a note; a front face has none. */
static void test_separate_specular_back(void)
{
    static uint8_t rgb[12] = {200, 150, 90, 200, 150, 90, 200, 150, 90, 200, 150, 90};
    free_res();
    add_bytes(rgb, sizeof rgb); /* the texels, id 1 */
    for (int back = 0; back < 2; back++) {
        interp *ip = fresh_depth();
        seq s;
        seq_init(&s);
        lit(&s);
        CMD(&s, LightModeli, GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
        CMD(&s, Materialfv, GL_FRONT, GL_SPECULAR, 0.5, 0.5, 0.5, 1);
        CMD(&s, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        CMD(&s, TexImage2D, GL_TEXTURE_2D, 0, GL_RGB, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, 1);
        CMD(&s, Enable, GL_TEXTURE_2D);
        tri(&s, back != 0);
        run(ip, &s);
        CHECK_EQ_U(sc.nmeshes, 1);
        CHECK_EQ_U(sc.ntris, 1);
        if (sc.nmeshes == 1)
            CHECK(sc.meshes[0].look.lit);
        CHECK_EQ_U(count(DIAG_NOTE_RELIT_SPECULAR), back ? 1 : 0);
        interp_destroy(ip);
    }
}

/* Fog: the triangles of a filled quad reaching behind the eye get their
 * own fog plane, GL's interpolated |z_eye| (exact, no note); lines or
 * outlines reaching behind are noted; a quad wholly in front, or one
 * without fog, is fogged by the eye-plane distance as before. */
static void test_fog_behind(void)
{
    for (int c = 0; c < 5; c++) {
        interp *ip = fresh_depth();
        seq s;
        seq_init(&s);
        CMD(&s, MatrixMode, GL_PROJECTION);
        CMD(&s, Frustum, -1, 1, -1, 1, 1, 20);
        CMD(&s, MatrixMode, GL_MODELVIEW);
        if (c != 2)
            CMD(&s, Enable, GL_FOG);
        if (c == 4)
            CMD(&s, PolygonMode, GL_FRONT_AND_BACK, GL_LINE);
        double near_z = c == 1 ? -2 : 3;
        CMD(&s, Begin, c == 3 ? GL_LINE_LOOP : GL_QUADS);
        CMD(&s, Vertex3f, -1, -1, near_z);
        CMD(&s, Vertex3f, 1, -1, near_z);
        CMD(&s, Vertex3f, 1, -1, -10);
        CMD(&s, Vertex3f, -1, -1, -10);
        CMD0(&s, End);
        run(ip, &s);
        CHECK_EQ_U(count(DIAG_NOTE_FOG_BEHIND), c >= 3 ? 1 : 0);
        /* Lines also carry the fog-on-lines note (GL_EXP: not affine in z). */
        CHECK_EQ_U(notes() - count(DIAG_NOTE_FOG_LINES), c >= 3 ? 1 : 0);
        size_t own = 0;
        for (size_t m = 0; m < sc.nmeshes; m++) {
            const scene_look *lk = &sc.meshes[m].look;
            if (!lk->fog_own)
                continue;
            own += sc.meshes[m].tri_count;
            /* the plane gives |z_eye| at each corner (identity modelview) */
            for (size_t t = 0; t < sc.meshes[m].tri_count; t++)
                for (int k = 0; k < 3; k++) {
                    const float *p = sc.verts[sc.tris[sc.meshes[m].first_tri + t].v[k]].pos;
                    double g = lk->fog_plane[0] * p[0] + lk->fog_plane[1] * p[1] +
                               lk->fog_plane[2] * p[2] + lk->fog_plane[3];
                    CHECK_NEAR(g, p[2] < 0 ? -p[2] : p[2], 1e-4);
                }
        }
        CHECK_EQ_U(own, c == 0 ? 2 : 0); /* both triangles of the quad */
        interp_destroy(ip);
    }
}

/* A lit triangle outlined (glPolygonMode GL_LINE, a larger one so that
 * its edges light pixels): its lines take GL's lit vertex colour
 * (DEFAULT_LIT) under one-sided lighting, not the material's 0.8; under
 * two-sided lighting that is not followed, and said. */
static void test_lit_outline(void)
{
    for (int two = 0; two < 2; two++) {
        interp *ip = fresh_depth();
        seq s;
        seq_init(&s);
        lit(&s);
        if (two)
            CMD(&s, LightModeli, GL_LIGHT_MODEL_TWO_SIDE, 1);
        CMD(&s, PolygonMode, GL_FRONT_AND_BACK, GL_LINE);
        CMD(&s, Begin, GL_TRIANGLES);
        CMD(&s, Vertex3f, -0.8, -0.8, -0.5);
        CMD(&s, Vertex3f, 0.8, -0.7, -0.5);
        CMD(&s, Vertex3f, 0.1, 0.8, -0.5);
        CMD0(&s, End);
        run(ip, &s);
        CHECK_EQ_U(sc.ntris, 0);
        CHECK(sc.nlines > 0);
        if (!two && sc.nlines > 0)
            CHECK_NEAR(sc.lines[0].color[0][0], DEFAULT_LIT, 1e-3);
        CHECK_EQ_U(dlog.e[DIAG_NOTE_LIT_OUTLINE].count, (uint64_t)two);
        interp_destroy(ip);
    }
}

int main(void)
{
    scene_init(&sc);
    fx_fetch = fetch_res;
    test_back_faces();
    test_mixed_strip();
    test_modulate_past_white();
    test_separate_specular_back();
    test_fog_behind();
    test_lit_outline();
    scene_finish(&sc);
    free_res();
    return CHECK_RESULT("test_relit");
}
