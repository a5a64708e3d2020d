/* test_gltf.c: the glTF writer (translate/gltf/gltfwrite.c) on scenes built by
 * hand: the GLB container, accessor bounds, one mesh placed by many nodes
 * for a display-list prototype, the material mapping, the camera against
 * the GL projection, lights, determinism, hostile names and allocation
 * failures.
 *
 *   test_gltf [DIR]   also writes each scene's .glb into DIR, for the
 *                     validator (test_validate.sh).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <GL/gl.h>

#include "../translate/check.h"
#include "../translate/scenes.h"
#include "format.h"
#include "frame.h"
#include "gltfwrite.h"
#include "mat4.h"
#include "scene.h"
#include "talloc.h"

#define PI 3.14159265358979323846

static const char *outdir;

static uint32_t le32(const uint8_t *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/* Writes s; checks the container; returns the JSON chunk as a string
 * (caller frees) and the stats. */
static char *write_glb(const scene *s, const char *name, gltf_stats *st, outbuf *keep)
{
    outbuf ob;
    CHECK(outbuf_init(&ob, 4096, NULL, NULL) == 0);
    gltf_frame_info info = {"test \"trace\"\n\xff.raygl", 3, name, NULL};
    CHECK(gltf_write(&ob, s, &info, st) == 0);
    CHECK(ob.len >= 20);
    const uint8_t *b = (const uint8_t *)ob.buf;
    CHECK(memcmp(b, "glTF", 4) == 0);
    CHECK_EQ_U(le32(b + 4), 2);
    CHECK_EQ_U(le32(b + 8), ob.len);
    uint32_t jl = le32(b + 12);
    CHECK_EQ_U(le32(b + 16), 0x4E4F534Au);
    CHECK(jl % 4 == 0 && 20 + (size_t)jl <= ob.len);
    if (20 + (size_t)jl < ob.len) {
        const uint8_t *c = b + 20 + jl;
        CHECK_EQ_U(le32(c + 4), 0x004E4942u);
        CHECK_EQ_U(20 + (size_t)jl + 8 + le32(c), ob.len);
    }
    char *json = malloc((size_t)jl + 1);
    memcpy(json, b + 20, jl);
    json[jl] = '\0';
    for (uint32_t i = 0; i < jl; i++)
        CHECK(json[i] >= 0x20 && json[i] < 0x7f);
    if (outdir && name) {
        char path[4096];
        snprintf(path, sizeof path, "%s/%s.glb", outdir, name);
        FILE *f = fopen(path, "wb");
        CHECK(f && fwrite(ob.buf, 1, ob.len, f) == ob.len && fclose(f) == 0);
    }
    if (keep)
        *keep = ob;
    else
        outbuf_finish(&ob);
    return json;
}

/* The number after the n-th (from 0) "key": in json; NAN when missing. */
static double jnum(const char *json, const char *key, int n)
{
    char k[64];
    snprintf(k, sizeof k, "\"%s\":", key);
    const char *p = json;
    for (int i = 0; p && i <= n; i++) {
        p = strstr(p, k);
        if (p && i < n)
            p += strlen(k);
    }
    if (!p)
        return NAN;
    p += strlen(k);
    if (*p == '[')
        p++;
    return strtod(p, NULL);
}

/* The i-th number of the array after the first "key":. */
static double jarr(const char *json, const char *key, int i)
{
    char k[64];
    snprintf(k, sizeof k, "\"%s\":[", key);
    const char *p = strstr(json, k);
    if (!p)
        return NAN;
    p += strlen(k);
    for (int j = 0; j < i; j++) {
        p = strchr(p, ',');
        if (!p)
            return NAN;
        p++;
    }
    return strtod(p, NULL);
}

static size_t count(const char *json, const char *needle)
{
    size_t n = 0;
    for (const char *p = strstr(json, needle); p; p = strstr(p + 1, needle))
        n++;
    return n;
}

static void camera_perspective(scene *s, double fovy, double aspect, double n, double f)
{
    mat4 p;
    int vp[4] = {0, 0, 400, (int)(400 / aspect)};
    CHECK(mat4_perspective(fovy, aspect, n, f, &p));
    CHECK(scene_camera_from_gl(&s->camera, &p, vp));
    s->have_camera = true;
}

static uint32_t vert(scene *s, float x, float y, float z, float r, float g, float b)
{
    scene_vertex *v = scene_reserve_vertices(s, 1);
    memset(v, 0, sizeof *v);
    v->pos[0] = x, v->pos[1] = y, v->pos[2] = z;
    v->normal[2] = 1;
    v->color[0] = r, v->color[1] = g, v->color[2] = b, v->color[3] = 1;
    v->tex[0] = x, v->tex[1] = y;
    scene_commit_vertices(s, 1);
    return (uint32_t)(s->nverts - 1);
}

static scene_look unlit(void)
{
    scene_look l;
    memset(&l, 0, sizeof l);
    l.material = l.texture = l.texture1 = -1;
    return l;
}

/* One triangle of known extent: the POSITION bounds are exactly its
 * eye-space corners. */
static void triangle(scene *s, const mat4 *m, const scene_look *look)
{
    CHECK(scene_mesh_for(s, m, false, look) != NULL);
    uint32_t a = vert(s, 0, 0, 0, 1, 0, 0), b = vert(s, 1, 0, 0, 0, 1, 0),
             c = vert(s, 0, 2, 0, 0, 0, 1);
    CHECK(scene_add_tri(s, a, b, c, c));
}

static void test_bounds_and_camera(void)
{
    scene s;
    scene_init(&s);
    camera_perspective(&s, 40, 4.0 / 3, 1, 30);
    mat4 m = mat4_translate(-1, 0.5, -5);
    scene_look l = unlit();
    triangle(&s, &m, &l);
    gltf_stats st;
    char *j = write_glb(&s, "bounds_camera", &st, NULL);
    /* red, green and blue corners: the interpolation in linear light noted */
    CHECK(strstr(j, "colours that vary across a face or line") != NULL);
    CHECK_NEAR(jarr(j, "min", 0), -1, 0);
    CHECK_NEAR(jarr(j, "min", 1), 0.5, 0);
    CHECK_NEAR(jarr(j, "min", 2), -5, 0);
    CHECK_NEAR(jarr(j, "max", 0), 0, 0);
    CHECK_NEAR(jarr(j, "max", 1), 2.5, 0);
    CHECK_NEAR(jarr(j, "max", 2), -5, 0);
    /* gluPerspective(40, 4/3, 1, 30) */
    CHECK(strstr(j, "\"type\":\"perspective\"") != NULL);
    CHECK_NEAR(jnum(j, "yfov", 0), 40 * PI / 180, 1e-6);
    CHECK_NEAR(jnum(j, "aspectRatio", 0), 4.0 / 3, 1e-6);
    CHECK_NEAR(jnum(j, "znear", 0), 1, 1e-5);
    CHECK_NEAR(jnum(j, "zfar", 0), 30, 1e-4);
    /* the camera at GL's eye, unturned */
    CHECK(strstr(j, "{\"name\":\"camera\",\"camera\":0}") != NULL);
    CHECK(strstr(j, "KHR_materials_unlit") != NULL);
    /* the trace's name escaped */
    CHECK(strstr(j, "\"source\":\"test \\\"trace\\\"\\u000a\\u00ff.raygl\"") != NULL);
    CHECK_EQ_U(st.meshes, 1);
    free(j);

    /* glOrtho(-4, 4, -3, 3, 2, 12): xmag 4, ymag 3, the camera moved to the
     * near plane. */
    mat4 o = mat4_ortho(-4, 4, -3, 3, 2, 12);
    int vp[4] = {0, 0, 400, 300};
    CHECK(scene_camera_from_gl(&s.camera, &o, vp));
    j = write_glb(&s, "ortho", NULL, NULL);
    CHECK(strstr(j, "\"type\":\"orthographic\"") != NULL);
    CHECK_NEAR(jnum(j, "xmag", 0), 4, 1e-5);
    CHECK_NEAR(jnum(j, "ymag", 0), 3, 1e-5);
    CHECK_NEAR(jnum(j, "znear", 0), 0, 0);
    CHECK_NEAR(jnum(j, "zfar", 0), 10, 1e-4);
    CHECK_NEAR(jarr(j, "translation", 2), -2, 1e-5);
    free(j);

    /* an off-axis frustum is noted */
    mat4 fr = mat4_frustum(-2, 1, -1, 3, 2, 10);
    CHECK(scene_camera_from_gl(&s.camera, &fr, vp));
    j = write_glb(&s, "offaxis", NULL, NULL);
    CHECK(strstr(j, "off-axis") != NULL);
    CHECK_NEAR(jnum(j, "yfov", 0), 2 * atan(2.0 / 2), 1e-6);
    free(j);
    scene_finish(&s);
}

static void test_instancing(void)
{
    scene s;
    scene_init(&s);
    camera_perspective(&s, 50, 1, 1, 100);
    scene_look l = unlit();
    mat4 id = mat4_identity();
    s.mesh_floor = 0;
    triangle(&s, &id, &l);
    s.meshes[0].proto = 1;
    scene_proto *pr = scene_add_proto(&s);
    pr->first_mesh = 0;
    pr->nmeshes = 1;
    for (int i = 0; i < 6; i++) {
        scene_instance *in = scene_add_instance(&s);
        in->proto = 0;
        mat4 t = mat4_translate(i - 3, 0, -10);
        mat4 r = mat4_rotate(30 * i, 0, 0, 1);
        in->to_eye = mat4_mul(&t, &r);
    }
    /* a sheared call: no TRS node matrix, so baked into a mesh of its own */
    scene_instance *in = scene_add_instance(&s);
    in->proto = 0;
    in->to_eye = mat4_translate(0, 3, -10);
    in->to_eye.m[4] = 0.5; /* x += 0.5 y */
    gltf_stats st;
    char *j = write_glb(&s, "instancing", &st, NULL);
    CHECK_EQ_U(st.instance_nodes, 6);
    CHECK_EQ_U(st.meshes, 2);
    CHECK_EQ_U(count(j, "\"mesh\":0"), 6);
    CHECK_EQ_U(count(j, "\"matrix\":"), 6);
    CHECK_EQ_U(st.accessors, 2 * 4); /* POSITION NORMAL COLOR_0 indices, twice */
    free(j);
    scene_finish(&s);
}

static int32_t material(scene *s, float r, float g, float b, float spec, float shin, uint8_t cm)
{
    scene_material m;
    memset(&m, 0, sizeof m);
    float d[4] = {r, g, b, 1};
    for (int f = 0; f < 2; f++) {
        memcpy(m.diffuse[f], d, sizeof d);
        for (int c = 0; c < 3; c++) {
            m.ambient[f][c] = 0.2f;
            m.specular[f][c] = spec;
        }
        m.ambient[f][3] = m.specular[f][3] = 1;
        m.shininess[f] = shin;
        m.color_material[f] = cm;
    }
    for (int c = 0; c < 3; c++)
        m.model_ambient[c] = 0.2f;
    m.model_ambient[3] = 1;
    return scene_material_index(s, &m);
}

static void test_materials_lights(void)
{
    scene s;
    scene_init(&s);
    camera_perspective(&s, 40, 4.0 / 3, 1, 30);
    scene_look l = unlit();
    l.lit = 1;
    l.material = material(&s, 0.7f, 0.25f, 0.2f, 0.3f, 30, 0);
    mat4 m = mat4_translate(0, 0, -5);
    triangle(&s, &m, &l);
    scene_look l2 = l;
    l2.material = material(&s, 0.5f, 0.5f, 0.5f, 0, 0, SCENE_CM_DIFFUSE | SCENE_CM_AMBIENT);
    l2.blend = SCENE_BLEND_ALPHA;
    mat4 m2 = mat4_translate(0, 0, -6);
    triangle(&s, &m2, &l2);
    scene_look l4 = unlit();
    l4.alpha_test = SCENE_ALPHA_ABOVE;
    l4.alpha_ref = 0.25f;
    mat4 m4 = mat4_translate(0, 0, -5.5);
    triangle(&s, &m4, &l4);
    scene_look l5 = unlit();
    l5.alpha_test = SCENE_ALPHA_NEVER;
    triangle(&s, &m4, &l5);
    scene_look l3 = unlit();
    l3.blend = SCENE_BLEND_INVISIBLE;
    mat4 m3 = mat4_translate(0, 0, -7);
    triangle(&s, &m3, &l3);

    scene_light *dl = scene_add_light(&s);
    memset(dl, 0, sizeof *dl);
    dl->kind = SCENE_LIGHT_PARALLEL;
    dl->direction[2] = 1; /* toward +z: shines along -z */
    dl->color[0] = dl->color[1] = dl->color[2] = 0.5f;
    dl->attenuation[0] = 1;
    scene_light *sp = scene_add_light(&s);
    memset(sp, 0, sizeof *sp);
    sp->kind = SCENE_LIGHT_SPOT;
    sp->position[1] = 4;
    sp->direction[1] = -1;
    sp->color[0] = sp->color[1] = sp->color[2] = 1;
    sp->spot_cutoff = 30;
    sp->spot_exponent = 10;
    sp->attenuation[0] = 2;
    gltf_stats st;
    char *j = write_glb(&s, "materials_lights", &st, NULL);
    CHECK_EQ_U(st.materials, 3);
    CHECK_EQ_U(st.meshes, 1);
    CHECK(count(j, "\"mode\":4") == 3); /* the invisible ones dropped */
    /* the alpha test GL_GREATER 0.25 */
    CHECK(strstr(j, "\"alphaMode\":\"MASK\",\"alphaCutoff\":0.25") != NULL);
    /* lit: diffuse as base colour (linear: GL's 0.7 is the display value
     * ((0.7 + 0.055) / 1.055)^2.4 = 0.448), (2 / (n + 2))^(1/4) roughness,
     * specular 0.3 (linear 0.0732) x 200 / (30 + 2) */
    CHECK_NEAR(jarr(j, "baseColorFactor", 0), 0.44798841, 1e-6);
    CHECK_NEAR(jarr(j, "baseColorFactor", 1), 0.05087609, 1e-6);
    CHECK_NEAR(jarr(j, "baseColorFactor", 3), 1, 0);
    CHECK_NEAR(jnum(j, "roughnessFactor", 0), 0.5, 1e-6);
    CHECK_NEAR(jarr(j, "specularColorFactor", 0), 0.07323896 * 200 / 32, 1e-6);
    CHECK_NEAR(jnum(j, "specularFactor", 0), 1, 0);
    CHECK_NEAR(jnum(j, "specularFactor", 1), 0, 0);
    /* GL's ambient: model 0.2 x material 0.2 = 0.04 into emissive (the
     * lights have no ambient), linear 0.04 / 12.92 */
    CHECK_NEAR(jarr(j, "emissiveFactor", 0), 0.04 / 12.92, 1e-6);
    CHECK(strstr(j, "lit surfaces: glTF viewers light in linear light") != NULL);
    CHECK(count(j, "\"alphaMode\":\"BLEND\"") == 1);
    CHECK(count(j, "\"doubleSided\":true") == 3);
    /* colour material: COLOR_0 on the second primitive (and the unlit one) */
    CHECK(count(j, "COLOR_0") == 2);
    /* lights: pi x GL's diffuse for the directional light; the spot's
     * constant attenuation 2 over the fitted 1/d^2 at the scene's centre */
    CHECK(strstr(j, "KHR_lights_punctual") != NULL);
    CHECK_EQ_U(st.lights, 2);
    /* (GL's 0.5 is linear 0.214) */
    CHECK_NEAR(jnum(j, "intensity", 0), 0.21404114 * PI, 1e-5);
    /* the first vertices' centre (0, 0, -5.5) lies 46.25^(1/2) from the spot */
    CHECK_NEAR(jnum(j, "intensity", 1), PI * 46.25 / 2, 1e-4);
    CHECK_NEAR(jnum(j, "outerConeAngle", 0), 30 * PI / 180, 1e-6);
    double half = acos(pow(0.5, 0.1));
    CHECK_NEAR(jnum(j, "innerConeAngle", 0), 2 * half - 30 * PI / 180, 1e-6);
    /* the spot aims down: -z turned to -y */
    CHECK(strstr(j, "rayglShadow") == NULL && strstr(j, "\"radiosity\"") == NULL);
    free(j);

    /* --area-lights and --radiosity (scene.options, the look step's): the
     * GL lights' soft size for Blender, POV-Ray's disc a tenth of the
     * distance to the scene's centre across (the sun: the angle it spans),
     * and the file's extras.radiosity */
    s.options.area_lights = 4;
    s.options.radiosity = true;
    j = write_glb(&s, "materials_lights_soft", &st, NULL);
    CHECK_NEAR(jnum(j, "rayglShadowAngle", 0), 2 * atan(0.05), 1e-6);
    CHECK_NEAR(jnum(j, "rayglShadowRadius", 0), 0.05 * sqrt(46.25), 1e-6);
    CHECK(strstr(j, "\"radiosity\":true") != NULL);
    CHECK(strstr(j, "area lights: glTF's lights are points") != NULL);
    free(j);
    s.options.no_shadows = true; /* nothing casts shadows: no size */
    j = write_glb(&s, "materials_lights_hard", &st, NULL);
    CHECK(strstr(j, "rayglShadow") == NULL);
    free(j);
    scene_finish(&s);
}

/* GL_COLOR_MATERIAL's ambient term follows the colour: one colour a draw
 * goes to emissive; faces of one colour each (a coloured cube) become one
 * primitive a colour; colours varying within a face keep none, noted. */
static void test_colour_material_ambient(void)
{
    scene s;
    scene_init(&s);
    camera_perspective(&s, 40, 4.0 / 3, 1, 30);
    scene_look l = unlit();
    l.lit = 1;
    l.material = material(&s, 0.5f, 0.5f, 0.5f, 0, 0, SCENE_CM_DIFFUSE | SCENE_CM_AMBIENT);
    mat4 m = mat4_translate(0, 0, -5);
    CHECK(scene_mesh_for(&s, &m, false, &l) != NULL);
    for (int f = 0; f < 2; f++) { /* a red face, then a green one */
        float r = f == 0, g = f == 1;
        uint32_t a = vert(&s, 0, 0, (float)f, r, g, 0), b = vert(&s, 1, 0, (float)f, r, g, 0),
                 c = vert(&s, 0, 1, (float)f, r, g, 0);
        CHECK(scene_add_tri(&s, a, b, c, c));
    }
    gltf_stats st;
    char *j = write_glb(&s, "cm_ambient_faces", &st, NULL);
    CHECK(count(j, "\"mode\":4") == 2);
    CHECK_EQ_U(st.materials, 2);
    /* model ambient 0.2 x the face's colour 1: display 0.2, linear 0.0331 */
    double lin02 = pow((0.2 + 0.055) / 1.055, 2.4);
    CHECK_NEAR(jarr(j, "emissiveFactor", 0), lin02, 1e-6);
    CHECK_NEAR(jarr(j, "emissiveFactor", 1), 0, 0);
    const char *second = strstr(strstr(j, "emissiveFactor") + 1, "emissiveFactor");
    CHECK(second != NULL);
    if (second) {
        CHECK_NEAR(jarr(second - 1, "emissiveFactor", 0), 0, 0);
        CHECK_NEAR(jarr(second - 1, "emissiveFactor", 1), lin02, 1e-6);
    }
    CHECK(strstr(j, "ambient term of a draw whose colours vary") == NULL);
    free(j);
    scene_finish(&s);

    /* colours varying within a face: no ambient term, and a note */
    scene_init(&s);
    camera_perspective(&s, 40, 4.0 / 3, 1, 30);
    l.material = material(&s, 0.5f, 0.5f, 0.5f, 0, 0, SCENE_CM_DIFFUSE | SCENE_CM_AMBIENT);
    triangle(&s, &m, &l);
    j = write_glb(&s, "cm_ambient_varying", &st, NULL);
    CHECK(count(j, "\"mode\":4") == 1);
    CHECK(strstr(j, "emissiveFactor") == NULL);
    CHECK(strstr(j, "ambient term of a draw whose colours vary") != NULL);
    free(j);
    scene_finish(&s);
}

/* A look's filter (a multiplying blend): glTF has alpha blending alone, so
 * what is behind keeps the mean of its weights (the vertex's own alpha
 * alone would leave a pure filter, alpha 0, invisible). */
static void test_filter_as_alpha(void)
{
    scene s;
    scene_init(&s);
    camera_perspective(&s, 40, 4.0 / 3, 1, 30);
    scene_look l = unlit();
    l.blend = SCENE_BLEND_ALPHA;
    l.filter = 0.5f;
    mat4 m = mat4_translate(0, 0, -5);
    CHECK(scene_mesh_for(&s, &m, false, &l) != NULL);
    uint32_t v[3];
    for (int k = 0; k < 3; k++) {
        v[k] = vert(&s, (float)(k == 1), (float)(k == 2), 0, 0.4f, 0.4f, 0.4f);
        s.verts[v[k]].color[3] = 0.2f;
    }
    CHECK(scene_add_tri(&s, v[0], v[1], v[2], v[2]));
    gltf_stats st;
    outbuf ob;
    char *j = write_glb(&s, "filter_as_alpha", &st, &ob);
    CHECK(strstr(j, "a filter): written as alpha") != NULL);
    CHECK(count(j, "\"alphaMode\":\"BLEND\"") == 1);
    /* transmit 1 - 0.5 - 0.2 = 0.3, behind kept 0.5 x 0.4 + 0.3 = 0.5: alpha
     * 0.5, colour 0.2 x 0.4 / 0.5 = 0.16 (linear 0.02217) */
    const char *c = strstr(j, "\"COLOR_0\":");
    CHECK(c != NULL);
    if (c) {
        int acc = atoi(c + strlen("\"COLOR_0\":"));
        int view = (int)jnum(j, "bufferView", acc);
        size_t off = (size_t)jnum(j, "byteOffset", view);
        const uint8_t *bin = (const uint8_t *)ob.buf + 20 + le32((const uint8_t *)ob.buf + 12) + 8;
        float col[4];
        memcpy(col, bin + off, sizeof col);
        CHECK_NEAR(col[3], 0.5, 1e-6);
        CHECK_NEAR(col[0], pow((0.16 + 0.055) / 1.055, 2.4), 1e-6);
    }
    outbuf_finish(&ob);
    free(j);
    scene_finish(&s);
}

static void test_solids_lines_textures(void)
{
    scene s;
    scene_init(&s);
    camera_perspective(&s, 60, 4.0 / 3, 0.5, 50);
    for (int k = 0; k <= SCENE_SOLID_TEAPOT; k++) {
        scene_solid *so = scene_add_solid(&s);
        memset(so, 0, sizeof *so);
        so->kind = (scene_solid_kind)k;
        so->params[0] = 1;
        so->params[1] = k == SCENE_SOLID_CONE ? 0 : 0.3;
        so->params[2] = 1.5;
        so->open = k == SCENE_SOLID_CONE;
        so->to_eye = mat4_translate(3 * k - 7.5, 0, -12);
        so->look = unlit();
        so->color[0] = 0.2f * (float)k;
        so->color[1] = so->color[3] = 1;
    }
    scene_line *ln = scene_add_line(&s);
    memset(ln, 0, sizeof *ln);
    ln->p[1][0] = 1;
    ln->p[0][2] = ln->p[1][2] = -3;
    ln->color[0][3] = ln->color[1][3] = 1;
    scene_point *pt = scene_add_point(&s);
    memset(pt, 0, sizeof *pt);
    pt->p[2] = -4;
    pt->color[3] = 1;
    scene_texture t;
    memset(&t, 0, sizeof t);
    t.width = 2;
    t.height = 2;
    t.rgba = tr_realloc(NULL, 16);
    for (int i = 0; i < 16; i++)
        t.rgba[i] = (uint8_t)(i * 16);
    t.repeat_s = true;
    t.border_t = true;
    t.linear = true;
    t.env_mode = SCENE_ENV_MODULATE;
    t.hash = 1;
    scene_look l = unlit();
    l.texture = scene_add_texture(&s, &t);
    CHECK(l.texture == 0);
    mat4 m = mat4_translate(0, 2, -8);
    triangle(&s, &m, &l);
    /* lit, GL_REPLACE: the texel alone, unlit */
    t.rgba = tr_realloc(NULL, 16);
    memset(t.rgba, 200, 16);
    t.env_mode = SCENE_ENV_REPLACE;
    t.colour_is_texel = true;
    t.hash = 2;
    scene_look lr = unlit();
    lr.texture = scene_add_texture(&s, &t);
    lr.lit = 1;
    lr.material = material(&s, 0.5f, 0.5f, 0.5f, 0, 0, 0);
    mat4 mr = mat4_translate(2, 2, -8);
    triangle(&s, &mr, &lr);
    gltf_stats st;
    char *j = write_glb(&s, "solids_lines_textures", &st, NULL);
    CHECK(count(j, "\"mode\":1") == 1);
    CHECK(count(j, "\"mode\":0") == 1);
    CHECK(count(j, "\"mode\":4") == 2 + SCENE_SOLID_TEAPOT + 1);
    CHECK_EQ_U(st.images, 2);
    CHECK(count(j, "KHR_materials_specular") == 0); /* the lit GL_REPLACE draw is unlit */
    CHECK(count(j, "\"baseColorTexture\":{\"index\":1},\"metallicFactor\":0},\"doubleSided\":true,"
                   "\"extensions\":{\"KHR_materials_unlit\":{}}") == 1);
    CHECK(strstr(j, "\"mimeType\":\"image/png\"") != NULL);
    CHECK(strstr(j, "\"wrapS\":10497,\"wrapT\":33071") != NULL);
    CHECK(strstr(j, "\"magFilter\":9729") != NULL);
    CHECK(strstr(j, "TEXCOORD_0") != NULL);
    CHECK(strstr(j, "border colour") != NULL);
    free(j);
    scene_finish(&s);
}

static void test_determinism_and_failures(void)
{
    scene s;
    scene_init(&s);
    camera_perspective(&s, 40, 1, 1, 30);
    scene_look l = unlit();
    for (int i = 0; i < 20; i++) {
        mat4 m = mat4_translate(i, 0, -5);
        l.flat = (uint8_t)(i % 2);
        triangle(&s, &m, &l);
    }
    outbuf a, b;
    free(write_glb(&s, NULL, NULL, &a));
    free(write_glb(&s, NULL, NULL, &b));
    CHECK(a.len == b.len && memcmp(a.buf, b.buf, a.len) == 0);
    outbuf_finish(&b);
    /* every allocation failing in turn: an error, never a crash or a
     * partial file that claims success */
    int fails = 0;
    for (unsigned long n = 1; n < 400; n++) {
        outbuf ob;
        if (outbuf_init(&ob, 4096, NULL, NULL) != 0)
            continue;
        tr_fail_alloc(n);
        int rc = gltf_write(&ob, &s, NULL, NULL);
        tr_fail_alloc(0);
        if (rc != 0)
            fails++;
        else
            CHECK(ob.len > 20 && memcmp(ob.buf, "glTF", 4) == 0);
        outbuf_finish(&ob);
    }
    CHECK(fails > 10);
    outbuf_finish(&a);
    scene_finish(&s);
}

/* Through the interpreter: the paper's box, then with the alpha test on. */
static void test_from_trace(void)
{
    seq q;
    seq_init(&q);
    scene_paper_box(&q);
    CMD(&q, Enable, GL_ALPHA_TEST);
    CMD(&q, AlphaFunc, GL_GEQUAL, 0.5);
    CMD(&q, Begin, GL_TRIANGLES);
    CMD(&q, Color4f, 1, 1, 1, 0.75);
    CMD(&q, Vertex3f, 0, 0, 0);
    CMD(&q, Vertex3f, 1, 0, 0);
    CMD(&q, Vertex3f, 0, 1, 0);
    CMD0(&q, End);
    trace t;
    trace_init(&t);
    trace_frame(&t, 0, 0, 0, 0, &q);
    trace_finish(&t);
    rgl_reader *r = NULL;
    CHECK(rgl_reader_open_memory(t.data, t.size, &r, NULL) == RGL_OK);
    translator *tr = r ? translator_create(r, NULL) : NULL;
    frame_result res;
    if (tr && translator_build(tr, 0, NULL, &res) == RGL_OK) {
        char *j = write_glb(translator_scene(tr), "paper_box_alpha", NULL, NULL);
        CHECK(strstr(j, "\"type\":\"orthographic\"") != NULL);
        CHECK_EQ_U(count(j, "\"alphaMode\":\"MASK\",\"alphaCutoff\":0.5"), 1);
        CHECK_EQ_U(count(j, "\"mode\":4"), 2);
        free(j);
    } else {
        CHECK(!"the paper's box translated");
    }
    translator_destroy(tr);
    rgl_reader_destroy(r);
    trace_free(&t);
    seq_free(&q);
}

int main(int argc, char **argv)
{
    outdir = argc > 1 ? argv[1] : NULL;
    test_bounds_and_camera();
    test_instancing();
    test_materials_lights();
    test_colour_material_ambient();
    test_filter_as_alpha();
    test_solids_lines_textures();
    test_determinism_and_failures();
    test_from_trace();
    return CHECK_RESULT("test_gltf");
}
