/* test_lights.c: light sets (interp_lightset.c) and how the writer lights
 * them (povwrite_light.c): one set per distinct group of lights in a frame,
 * light_group only with more than one, one shadow-casting light per GL light
 * with shadows and the exact split with --no-shadows, and the highlight
 * multiple of a set.
 */
#include <GL/gl.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "interp_fixture.h"
#include "interp.h"
#include "interp_internal.h"
#include "outbuf.h"
#include "povwrite.h"
#include "scene.h"
#include "tracegen.h"

static void write_scene(bool no_shadows)
{
    pov_frame_info info;
    memset(&info, 0, sizeof info);
    sc.options.no_shadows = no_shadows;
    write_sdl_with(NULL, &info);
    sc.options.no_shadows = false;
}

static void tri(seq *s, float z)
{
    CMD(s, Begin, GL_TRIANGLES);
    CMD(s, Vertex3f, 0, 0, z);
    CMD(s, Vertex3f, 1, 0, z);
    CMD(s, Vertex3f, 0, 1, z);
    CMD0(s, End);
}

/* A, B, A: two sets, the third draw back in the first; the writer puts each
 * set's objects in a light_group with its lights. */
static void test_sets(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Enable, GL_LIGHTING);
    CMD(&s, Enable, GL_LIGHT0);
    tri(&s, -2);
    CMD(&s, Lightfv, GL_LIGHT0, GL_DIFFUSE, 1, 0, 0, 1); /* recoloured */
    tri(&s, -3);
    CMD(&s, Lightfv, GL_LIGHT0, GL_DIFFUSE, 1, 1, 1, 1); /* back */
    tri(&s, -4);
    run(ip, &s);
    interp_end_frame(ip);
    CHECK_EQ_U(sc.nlightsets, 2);
    CHECK_EQ_U(sc.nlights, 2);
    CHECK_EQ_U(sc.nmeshes, 3);
    if (sc.nmeshes == 3) {
        CHECK(sc.materials[sc.meshes[0].look.material].lightset == 0);
        CHECK(sc.materials[sc.meshes[1].look.material].lightset == 1);
        CHECK(sc.materials[sc.meshes[2].look.material].lightset == 0);
    }
    CHECK_EQ_U(count(DIAG_NOTE_LIGHTING), 0);
    CHECK_EQ_U(count(DIAG_NOTE_SHADOW_HIGHLIGHT), 1); /* red diffuse, white specular */
    CHECK_EQ_U(dlog.e[DIAG_NOTE_SHADOW_HIGHLIGHT].held, 0);
    write_scene(true);
    CHECK_EQ_U(occurrences(sdl, "light_group{"), 2);
    CHECK_EQ_U(occurrences(sdl, "global_lights on}"), 2);
    /* --no-shadows: LIGHT0 white (one light of ls = ld), then red with
     * white specular: ls and a shadowless ld - ls. */
    CHECK_EQ_U(occurrences(sdl, "light_source{"), 3);
    CHECK_EQ_U(occurrences(sdl, "shadowless"), 1);
    interp_destroy(ip);
}

/* One set: no light_group. With shadows, a light whose specular differs
 * from its diffuse is one shadow-casting light of its diffuse colour, and
 * the finish's specular is the set's multiple of the material's. */
static void test_one_set_shadows(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Enable, GL_LIGHTING);
    CMD(&s, Enable, GL_LIGHT1);
    CMD(&s, Lightfv, GL_LIGHT1, GL_DIFFUSE, 0.5, 0.5, 0.5, 1);
    CMD(&s, Lightfv, GL_LIGHT1, GL_SPECULAR, 0.25, 0.25, 0.25, 1);
    CMD(&s, Materialfv, GL_FRONT, GL_SPECULAR, 0.8, 0.8, 0.8, 1);
    tri(&s, -2);
    tri(&s, -3);
    run(ip, &s);
    interp_end_frame(ip);
    CHECK_EQ_U(sc.nlightsets, 1);
    CHECK_EQ_U(count(DIAG_NOTE_SHADOW_HIGHLIGHT), 0); /* 0.25 = 0.5 x 0.5: exact */
    write_scene(false);
    CHECK_EQ_U(occurrences(sdl, "light_group{"), 0);
    CHECK_EQ_U(occurrences(sdl, "light_source{"), 1);
    CHECK_EQ_U(occurrences(sdl, "shadowless"), 0);
    CHECK(strstr(sdl, "rgb<0.5,0.5,0.5>") != NULL);
    CHECK(strstr(sdl, "specular 0.4 ") != NULL); /* 0.8 x 0.5 */
    write_scene(true);
    CHECK_EQ_U(occurrences(sdl, "light_source{"), 2);
    CHECK_EQ_U(occurrences(sdl, "shadowless"), 1);
    CHECK(strstr(sdl, "specular 0.8 ") != NULL);
    interp_destroy(ip);
}

/* With shadows, a light whose specular is a multiple of its diffuse per
 * channel: a light of its specular colour, the pigment the diffuse
 * material divided by those multiples, the specular unscaled: exact, so
 * no note. */
static void test_channels(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Enable, GL_LIGHTING);
    CMD(&s, Enable, GL_LIGHT0);
    CMD(&s, Lightfv, GL_LIGHT0, GL_DIFFUSE, 0.5, 0.25, 1, 1);
    CMD(&s, Lightfv, GL_LIGHT0, GL_SPECULAR, 0.25, 0.25, 0.25, 1);
    CMD(&s, Materialfv, GL_FRONT, GL_SPECULAR, 0.5, 0.5, 0.5, 1);
    tri(&s, -2);
    run(ip, &s);
    interp_end_frame(ip);
    CHECK_EQ_U(count(DIAG_NOTE_SHADOW_HIGHLIGHT), 0);
    write_scene(false);
    CHECK_EQ_U(occurrences(sdl, "light_source{"), 1);
    CHECK(strstr(sdl, "rgb<0.25,0.25,0.25>") != NULL);
    CHECK(strstr(sdl, "pigment{rgb<1.6,0.8,3.2>}") != NULL); /* 0.8 / (0.5, 1, 0.25) */
    CHECK(strstr(sdl, "specular 0.5 ") != NULL);
    write_scene(true); /* --no-shadows: the split, the material's own pigment */
    CHECK(strstr(sdl, "pigment{rgb<0.8,0.8,0.8>}") != NULL);
    interp_destroy(ip);
    double t[3];
    scene_light l;
    memset(&l, 0, sizeof l);
    l.color[0] = 1, l.specular[0] = 1; /* green and blue: no specular */
    CHECK(!scene_lights_specular_channels(&l, 1, t));
}

/* A set whose draws a glClear erased is not written: the one set left is
 * written as a frame of one set. */
static void test_cleared_set(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Enable, GL_LIGHTING);
    CMD(&s, Enable, GL_LIGHT0);
    tri(&s, -2);
    CMD(&s, Clear, GL_COLOR_BUFFER_BIT);
    CMD(&s, Disable, GL_LIGHT0);
    CMD(&s, Enable, GL_LIGHT2);
    tri(&s, -3);
    run(ip, &s);
    interp_end_frame(ip);
    CHECK_EQ_U(sc.nlightsets, 2);
    write_scene(true);
    CHECK_EQ_U(occurrences(sdl, "light_group{"), 0);
    /* LIGHT2's default: black diffuse and specular, so no light at all */
    CHECK_EQ_U(occurrences(sdl, "light_source{"), 0);
    interp_destroy(ip);
}

/* A trace that changes its lights at every draw: at most
 * SCENE_MAX_LIGHTSETS sets, then a note. */
static void test_set_cap(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Enable, GL_LIGHTING);
    CMD(&s, Enable, GL_LIGHT0);
    for (int i = 0; i < SCENE_MAX_LIGHTSETS + 10; i++) {
        CMD(&s, Lightf, GL_LIGHT0, GL_CONSTANT_ATTENUATION, 1.0 + i);
        tri(&s, -2);
    }
    /* Back to the fourth set's lights: found again, not noted. */
    CMD(&s, Lightf, GL_LIGHT0, GL_CONSTANT_ATTENUATION, 4.0);
    tri(&s, -3);
    run(ip, &s);
    interp_end_frame(ip);
    CHECK_EQ_U(sc.nlightsets, SCENE_MAX_LIGHTSETS);
    CHECK_EQ_U(sc.nlights, SCENE_MAX_LIGHTSETS);
    if (sc.nmeshes > 0) {
        const scene_mesh *m = &sc.meshes[sc.nmeshes - 1];
        CHECK(m->look.material >= 0 && sc.materials[m->look.material].lightset == 3);
    }
    CHECK_EQ_U(count(DIAG_NOTE_LIGHTING), 1); /* a note is said once a frame */
    /* The next frame starts with no sets. */
    scene_reset(&sc);
    interp_begin_frame(ip);
    seq_init(&s);
    CMD(&s, Lightf, GL_LIGHT0, GL_CONSTANT_ATTENUATION, 2.0);
    tri(&s, -2);
    run(ip, &s);
    CHECK_EQ_U(sc.nlightsets, 1);
    CHECK_EQ_U(sc.nlights, 1);
    interp_destroy(ip);
}

/* The highlight multiple: least squares over the channels; exact only when
 * every light's specular is that multiple of its diffuse. */
static void test_ratio(void)
{
    scene_light l[2];
    memset(l, 0, sizeof l);
    for (int k = 0; k < 3; k++) {
        l[0].color[k] = 1, l[0].specular[k] = 1;
        l[1].color[k] = 0.5f, l[1].specular[k] = 0;
    }
    double r;
    CHECK(scene_lights_specular_ratio(l, 1, &r));
    CHECK_NEAR(r, 1, 1e-12);
    CHECK(!scene_lights_specular_ratio(l, 2, &r));
    CHECK_NEAR(r, 3.0 / 3.75, 1e-12);
    CHECK(scene_lights_specular_ratio(l + 1, 1, &r));
    CHECK_NEAR(r, 0, 0);
}

/* After glDrawArrays the current colour, normal and the materials colour
 * material tracks are those from before the draw (Mesa); glArrayElement
 * keeps the element's. */
static void test_array_current(void)
{
    interp *ip = fresh();
    static const float pos[3][2] = {{0, 0}, {1, 0}, {0, 1}};
    static const float col[3][4] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0.1f, 0.2f, 0.3f, 1}};
    static const float nrm[3][3] = {{1, 0, 0}, {1, 0, 0}, {1, 0, 0}};
    seq s;
    seq_init(&s);
    CMD(&s, Enable, GL_LIGHTING);
    CMD(&s, Color3f, 0.9, 0.6, 0.2);
    CMD(&s, Normal3f, 0, 0, 1);
    CMD(&s, ColorMaterial, GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
    CMD(&s, Enable, GL_COLOR_MATERIAL);
    for (int pass = 0; pass < 2; pass++) {
        seq_cmd_bytes(&s, RGL_OP_ArrayData, pos, sizeof pos,
                      (const double[]){GL_VERTEX_ARRAY, 0, 2, GL_FLOAT}, 4);
        seq_cmd_bytes(&s, RGL_OP_ArrayData, col, sizeof col,
                      (const double[]){GL_COLOR_ARRAY, 0, 4, GL_FLOAT}, 4);
        seq_cmd_bytes(&s, RGL_OP_ArrayData, nrm, sizeof nrm,
                      (const double[]){GL_NORMAL_ARRAY, 0, 3, GL_FLOAT}, 4);
        if (pass == 0)
            CMD(&s, DrawArrays, GL_TRIANGLES, 0, 3);
        else
            CMD(&s, ArrayElement, 2);
    }
    run(ip, &s);
    const gl_attribs *a = &interp_state(ip)->a;
    CHECK_EQ_U(sc.nverts, 3);
    if (sc.nverts == 3)
        CHECK_NEAR(sc.verts[2].color[2], 0.3, 1e-6); /* each vertex its element's */
    /* after the glArrayElement: the element's */
    CHECK_NEAR(a->current.color[0], 0.1, 1e-6);
    CHECK_NEAR(a->current.normal[0], 1, 0);
    interp_destroy(ip);

    ip = fresh();
    seq_init(&s);
    CMD(&s, Enable, GL_LIGHTING);
    CMD(&s, Color3f, 0.9, 0.6, 0.2);
    CMD(&s, Normal3f, 0, 0, 1);
    CMD(&s, ColorMaterial, GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
    CMD(&s, Enable, GL_COLOR_MATERIAL);
    seq_cmd_bytes(&s, RGL_OP_ArrayData, pos, sizeof pos,
                  (const double[]){GL_VERTEX_ARRAY, 0, 2, GL_FLOAT}, 4);
    seq_cmd_bytes(&s, RGL_OP_ArrayData, col, sizeof col,
                  (const double[]){GL_COLOR_ARRAY, 0, 4, GL_FLOAT}, 4);
    seq_cmd_bytes(&s, RGL_OP_ArrayData, nrm, sizeof nrm,
                  (const double[]){GL_NORMAL_ARRAY, 0, 3, GL_FLOAT}, 4);
    CMD(&s, DrawArrays, GL_TRIANGLES, 0, 3);
    run(ip, &s);
    a = &interp_state(ip)->a;
    CHECK_NEAR(a->current.color[0], 0.9, 1e-6);
    CHECK_NEAR(a->current.color[2], 0.2, 1e-6);
    CHECK_NEAR(a->current.normal[2], 1, 0);
    CHECK_NEAR(a->lighting.material[0].ambient[1], 0.6, 1e-6);
    interp_destroy(ip);
}

/* glMaterial between vertices: the varying term rides on the vertex
 * colours as colour material would; a change after the last vertex lights
 * nothing; two varying colours are noted. (Emissions of 0.1: lit to 0.94,
 * below white, so POV-Ray lights the face; past white it is relit.) */
static void test_vertex_material(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Enable, GL_LIGHTING);
    CMD(&s, Enable, GL_LIGHT0);
    CMD(&s, Begin, GL_TRIANGLES);
    CMD(&s, Materialfv, GL_FRONT, GL_EMISSION, 0.1, 0, 0, 1);
    CMD(&s, Vertex3f, 0, 0, -2);
    CMD(&s, Materialfv, GL_FRONT, GL_EMISSION, 0, 0.1, 0, 1);
    CMD(&s, Vertex3f, 1, 0, -2);
    CMD(&s, Vertex3f, 0, 1, -2);
    CMD(&s, Materialfv, GL_FRONT, GL_DIFFUSE, 0, 0, 1, 1); /* after the last vertex */
    CMD0(&s, End);
    run(ip, &s);
    CHECK_EQ_U(sc.nmaterials, 1);
    CHECK_EQ_U(sc.nverts, 3);
    if (sc.nmaterials == 1 && sc.nverts == 3) {
        const scene_material *m = &sc.materials[0];
        CHECK(m->color_material[0] == SCENE_CM_EMISSION && m->color_material[1] == SCENE_CM_EMISSION);
        CHECK_NEAR(m->diffuse[0][0], 0.8, 1e-6); /* GL's default, not the late blue */
        CHECK_NEAR(sc.verts[0].color[0], 0.1, 1e-6);
        CHECK_NEAR(sc.verts[1].color[1], 0.1, 1e-6);
        CHECK_NEAR(sc.verts[2].color[1], 0.1, 1e-6);
    }
    /* The state after glEnd is GL's: the late blue holds. */
    CHECK_NEAR(interp_state(ip)->a.lighting.material[0].diffuse[2], 1, 0);
    CHECK_EQ_U(count(DIAG_NOTE_MATERIAL_VERTEX), 0);
    seq_init(&s);
    CMD(&s, Begin, GL_TRIANGLES);
    CMD(&s, Materialfv, GL_FRONT, GL_DIFFUSE, 1, 0, 0, 1);
    CMD(&s, Vertex3f, 0, 0, -2);
    CMD(&s, Materialfv, GL_FRONT, GL_AMBIENT, 0, 1, 0, 1);
    CMD(&s, Materialfv, GL_FRONT, GL_DIFFUSE, 0, 0, 1, 1);
    CMD(&s, Vertex3f, 1, 0, -2);
    CMD(&s, Vertex3f, 0, 1, -2);
    CMD0(&s, End);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_NOTE_MATERIAL_VERTEX), 1);
    interp_destroy(ip);
}

/* GL_COLOR_MATERIAL as Mesa 22 follows it (measured with OSMesa; see
 * interp_light.c "Colour material"): each case from a fresh interpreter,
 * its front diffuse red channel after the commands. The material's diffuse
 * is grey (0.4), the current colour red unless said. */
static float cm_case(int k)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Enable, GL_LIGHTING);
    CMD(&s, Color3f, 1, 0, 0);
    CMD(&s, Materialfv, GL_FRONT_AND_BACK, GL_DIFFUSE, 0.4, 0.4, 0.4, 1);
    switch (k) {
    case 0: /* a glMaterial since the last draw: the glEnable keeps it */
        CMD(&s, Enable, GL_COLOR_MATERIAL);
        tri(&s, -2);
        break;
    case 1: /* a draw in between: the glEnable copies the colour */
        tri(&s, -2);
        CMD(&s, Enable, GL_COLOR_MATERIAL);
        break;
    case 2: /* a glColor that ends where it started counts for nothing */
        CMD(&s, Enable, GL_COLOR_MATERIAL);
        CMD(&s, Color3f, 0, 1, 0);
        CMD(&s, Color3f, 1, 0, 0);
        tri(&s, -2);
        break;
    case 3: /* after a draw, any glColor counts */
        CMD(&s, Enable, GL_COLOR_MATERIAL);
        tri(&s, -2);
        CMD(&s, Color3f, 1, 0, 0);
        break;
    case 4: /* a second glEnable copies it */
        CMD(&s, Enable, GL_COLOR_MATERIAL);
        CMD(&s, Disable, GL_COLOR_MATERIAL);
        CMD(&s, Enable, GL_COLOR_MATERIAL);
        break;
    case 5: /* a colour change seen at the glDisable */
        CMD(&s, Enable, GL_COLOR_MATERIAL);
        CMD(&s, Color3f, 0.5, 0, 0);
        CMD(&s, Disable, GL_COLOR_MATERIAL);
        break;
    case 6: /* glColorMaterial naming another mode copies it */
        CMD(&s, Enable, GL_COLOR_MATERIAL);
        CMD(&s, ColorMaterial, GL_FRONT_AND_BACK, GL_DIFFUSE);
        break;
    case 7: /* Mesa's vertex buffer flushed at glPushAttrib/glPopAttrib */
        CMD(&s, PushAttrib, GL_LIGHTING_BIT);
        CMD0(&s, PopAttrib);
        CMD(&s, Enable, GL_COLOR_MATERIAL);
        break;
    default: /* glMaterial of a tracked term while on: nothing */
        tri(&s, -2);
        CMD(&s, Enable, GL_COLOR_MATERIAL);
        CMD(&s, Materialfv, GL_FRONT_AND_BACK, GL_DIFFUSE, 0, 0, 1, 1);
        CMD(&s, Disable, GL_COLOR_MATERIAL);
        break;
    }
    run(ip, &s);
    float r = interp_state(ip)->a.lighting.material[0].diffuse[0];
    if (k == 0 || k == 2) { /* the draw lights with the material, not the colour */
        CHECK(sc.nmaterials == 1 && sc.materials[0].color_material[0] == 0);
        CHECK(sc.nmaterials == 1 && sc.materials[0].diffuse[0][0] == 0.4f);
    }
    interp_destroy(ip);
    return r;
}

static void test_color_material_enable(void)
{
    static const float want[9] = {0.4f, 1, 0.4f, 1, 1, 0.5f, 1, 1, 1};
    for (int k = 0; k < 9; k++) {
        float r = cm_case(k);
        if (r != want[k])
            fprintf(stderr, "colour material case %d: diffuse red %g, want %g\n", k, (double)r,
                    (double)want[k]);
        CHECK(r == want[k]);
    }
}

/* --vertex-lighting: a lit triangle drawn unlit in GL's lit colours;
 * two-sided lighting keeps POV-Ray's. LIGHT0 along -z onto the normal
 * (0, 0, 1): e + a Ga + d (N.L) = 0.2 x 0.2 + 0.8 = 0.84 per channel. */
static void test_vertex_lighting(void)
{
    interp *ip = fresh();
    interp_set_vertex_lighting(ip, true);
    seq s;
    seq_init(&s);
    CMD(&s, Enable, GL_LIGHTING);
    CMD(&s, Enable, GL_LIGHT0);
    CMD(&s, Normal3f, 0, 0, 1);
    tri(&s, -2);
    CMD(&s, LightModeli, GL_LIGHT_MODEL_TWO_SIDE, 1);
    tri(&s, -3);
    run(ip, &s);
    CHECK_EQ_U(sc.nmeshes, 2);
    if (sc.nmeshes == 2) {
        CHECK(!sc.meshes[0].look.lit && sc.meshes[0].look.material < 0);
        CHECK(sc.meshes[1].look.lit);
    }
    if (sc.nverts >= 3)
        CHECK_NEAR(sc.verts[0].color[0], 0.84, 1e-6);
    interp_destroy(ip);
}

/* A face large against its distance to a point light is noted (lit per
 * pixel, not at its corners); not under a directional light, nor with
 * --vertex-lighting. */
static void test_gouraud_note(void)
{
    for (int c = 0; c < 3; c++) {
        interp *ip = fresh();
        interp_set_vertex_lighting(ip, c == 2);
        seq s;
        seq_init(&s);
        CMD(&s, Enable, GL_LIGHTING);
        CMD(&s, Enable, GL_LIGHT0);
        CMD(&s, Lightfv, GL_LIGHT0, GL_POSITION, 0, 0, -1, c == 1 ? 0 : 1);
        CMD(&s, Begin, GL_TRIANGLES);
        CMD(&s, Vertex3f, -2, -2, -2);
        CMD(&s, Vertex3f, 2, -2, -2);
        CMD(&s, Vertex3f, 0, 2, -2);
        CMD0(&s, End);
        run(ip, &s);
        CHECK_EQ_U(count(DIAG_NOTE_GOURAUD), c == 0 ? 1 : 0);
        interp_destroy(ip);
    }
}

/* glTF output (issue 27): the notes of POV-Ray's renders of the lights
 * are held, not said, as no POV-Ray render is made. */
static void test_gltf_notes(void)
{
    for (int spot = 0; spot < 2; spot++) {
        interp *ip = fresh();
        interp_set_pov(ip, false);
        interp_set_shadows(ip, spot == 0);
        seq s;
        seq_init(&s);
        CMD(&s, Enable, GL_LIGHTING);
        CMD(&s, Enable, GL_LIGHT0);
        if (spot) {
            CMD(&s, Lightfv, GL_LIGHT0, GL_POSITION, 0, 0, 0, 1);
            CMD(&s, Lightf, GL_LIGHT0, GL_SPOT_CUTOFF, 30);
            CMD(&s, Lightfv, GL_LIGHT0, GL_SPECULAR, 0.5, 0.5, 0.5, 1);
        } else {
            CMD(&s, Lightfv, GL_LIGHT0, GL_DIFFUSE, 1, 0, 0, 1); /* white specular */
        }
        tri(&s, -2);
        run(ip, &s);
        interp_end_frame(ip);
        diag_kind k = spot ? DIAG_NOTE_SPOT_SPECULAR : DIAG_NOTE_SHADOW_HIGHLIGHT;
        CHECK_EQ_U(count(k), 1);
        CHECK_EQ_U(dlog.e[k].held, 1);
        interp_destroy(ip);
    }
}

int main(void)
{
    scene_init(&sc);
    test_sets();
    test_one_set_shadows();
    test_channels();
    test_cleared_set();
    test_set_cap();
    test_ratio();
    test_array_current();
    test_vertex_material();
    test_color_material_enable();
    test_vertex_lighting();
    test_gouraud_note();
    test_gltf_notes();
    scene_finish(&sc);
    return CHECK_RESULT("test_lights");
}
