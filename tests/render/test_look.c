/* test_look.c: the camera, light and size overrides (translate/look/look.c).
 *
 * The animated trace's frames use gluLookAt(0,3,7 -> 0,0,0) and
 * gluPerspective(45): overriding the camera with those same values in world
 * coordinates, or with the identity view in eye coordinates, must give back
 * the translated camera; an added light at the eye sits at the eye-space
 * origin; sizes keep the aspect ratio.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <GL/gl.h>

#include "anim.h"
#include "check.h"
#include "frame.h"
#include "look.h"
#include "options.h"
#include "povwrite_look.h"

static translator *tr;
static rgl_reader *reader;

static scene *build(int lookat)
{
    trace t;
    seq s;
    trace_init(&t);
    seq_init(&s);
    if (lookat) {
        anim_frame(&s, 0, 1, 160, 120);
    } else {
        /* The same view made with glTranslate: no view transform to separate. */
        CMD(&s, Viewport, 0, 0, 160, 120);
        CMD(&s, MatrixMode, GL_PROJECTION);
        CMD(&s, Perspective, 45, 160.0 / 120, 0.5, 50);
        CMD(&s, MatrixMode, GL_MODELVIEW);
        CMD(&s, Translatef, 0, 0, -5);
        CMD(&s, Begin, GL_TRIANGLES);
        CMD(&s, Vertex3f, 0, 0, 0);
        CMD(&s, Vertex3f, 1, 0, 0);
        CMD(&s, Vertex3f, 0, 1, 0);
        CMD0(&s, End);
    }
    trace_frame(&t, 0, 0, 0, 0, &s);
    seq_free(&s);
    trace_finish(&t);
    static uint8_t copy[1 << 20];
    CHECK(t.size <= sizeof copy);
    memcpy(copy, t.data, t.size);
    rgl_reader_destroy(reader);
    translator_destroy(tr);
    CHECK(rgl_reader_open_memory(copy, t.size, &reader, NULL) == RGL_OK);
    tr = translator_create(reader, NULL);
    frame_result res;
    CHECK(translator_build(tr, 0, NULL, &res) == RGL_OK);
    trace_free(&t);
    return translator_scene_edit(tr);
}

/* Same rays: same location, and direction, up and right equal up to one
 * common scale (POV-Ray's camera only uses their ratios). */
static void check_cam(const scene_camera *a, const scene_camera *b, const char *what)
{
    const double *va[4] = {a->location, a->direction, a->up, a->right};
    const double *vb[4] = {b->location, b->direction, b->up, b->right};
    double la = sqrt(a->direction[0] * a->direction[0] + a->direction[1] * a->direction[1] +
                     a->direction[2] * a->direction[2]);
    double lb = sqrt(b->direction[0] * b->direction[0] + b->direction[1] * b->direction[1] +
                     b->direction[2] * b->direction[2]);
    double worst = 0;
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 3; k++)
            worst = fmax(worst, i == 0 ? fabs(va[i][k] - vb[i][k])
                                       : fabs(va[i][k] / la - vb[i][k] / lb));
    printf("%s: largest camera difference %.3g\n", what, worst);
    CHECK(worst < 1e-6);
    CHECK(a->kind == SCENE_CAMERA_PERSPECTIVE || a->kind == SCENE_CAMERA_LOOKAT);
}

static bool set(options *o, bool (*fn)(options *, const char *, const opt_ctx *, opt_err *),
                const char *v)
{
    opt_ctx ctx = {NULL, 0, "--x"};
    opt_err err;
    bool ok = fn(o, v, &ctx, &err);
    if (!ok)
        printf("  (%s: %s)\n", v, err.msg);
    return ok;
}

int main(void)
{
    options o;

    /* World coordinates: the program's own gluLookAt gives back its camera. */
    scene *s = build(1);
    CHECK(s->have_view);
    scene_camera orig = s->camera;
    opt_init(&o);
    CHECK(set(&o, opt_set_camera_location, "0,3,7"));
    CHECK(set(&o, opt_set_camera_look_at, "0,0,0"));
    CHECK(set(&o, opt_set_camera_up, "0,1,0"));
    CHECK(set(&o, opt_set_camera_fov, "45"));
    const char *note;
    CHECK(look_apply(&o.look, s, &note) == 0);
    CHECK(note && strstr(note, "world"));
    check_cam(&s->camera, &orig, "world override = gluLookAt");
    CHECK(!s->camera.has_clip);

    /* A light at the eye is at the eye-space origin. */
    CHECK(set(&o, opt_set_light, "point at=0,3,7 color=1,0.5,0.25"));
    CHECK(set(&o, opt_set_light, "spot at=0,3,7 to=0,0,0 radius=10 falloff=20"));
    s = build(1);
    CHECK(look_apply(&o.look, s, &note) == 0);
    CHECK(s->nlights >= 2 && s->lights[s->nlights - 1].added);
    outbuf ob;
    static char text[4096];
    size_t len = 0;
    CHECK(outbuf_init(&ob, 4096, NULL, NULL) == 0);
    povlook_scene(&ob, s);
    CHECK(!ob.failed);
    len = ob.len < sizeof text - 1 ? ob.len : sizeof text - 1;
    memcpy(text, ob.buf, len);
    text[len] = '\0';
    outbuf_finish(&ob);
    printf("%s", text);
    CHECK(strstr(text, "light_source{<0,0,0> rgb<1,0.5,0.25>}") != NULL);
    /* The spot points down the eye's -z, 7.6158 away (|(0,3,7)|). */
    CHECK(strstr(text, "light_source{<0,0,0> rgb<1,1,1> spotlight point_at<0,") != NULL);
    CHECK(strstr(text, ",-7.615773> radius 10 falloff 20}") != NULL);
    opt_free(&o);

    /* Eye coordinates on request: the identity view. */
    s = build(1);
    opt_init(&o);
    CHECK(set(&o, opt_set_override_space, "eye"));
    CHECK(set(&o, opt_set_camera_location, "0,0,0"));
    CHECK(set(&o, opt_set_camera_look_at, "0,0,-1"));
    CHECK(look_apply(&o.look, s, &note) == 0);
    CHECK(note && strstr(note, "eye"));
    check_cam(&s->camera, &orig, "eye override = GL camera");
    opt_free(&o);

    /* No gluLookAt: eye coordinates, and only the location moves. */
    s = build(0);
    CHECK(!s->have_view);
    scene_camera o2 = s->camera;
    opt_init(&o);
    CHECK(set(&o, opt_set_camera_location, "1,2,3"));
    CHECK(look_apply(&o.look, s, &note) == 0);
    CHECK(note && strstr(note, "eye coordinates"));
    CHECK(fabs(s->camera.location[0] - 1) < 1e-9 && fabs(s->camera.location[2] - 3) < 1e-9);
    double d0 = o2.direction[2] / sqrt(o2.direction[0] * o2.direction[0] +
                                       o2.direction[1] * o2.direction[1] +
                                       o2.direction[2] * o2.direction[2]);
    double d1 = s->camera.direction[2] / sqrt(s->camera.direction[0] * s->camera.direction[0] +
                                              s->camera.direction[1] * s->camera.direction[1] +
                                              s->camera.direction[2] * s->camera.direction[2]);
    CHECK_NEAR(d1, d0, 1e-9);
    opt_free(&o);

    /* --camera-orthographic alone (issue 27): the perspective view's
     * framing at the depth it looked at, gluLookAt's centre |(0,3,7)| away
     * (a view 1 away framed a close-up before: height 0.83), or without
     * gluLookAt the centre of what the frame drew, the triangle 5 away. */
    const double t22 = tan(22.5 * 3.14159265358979323846 / 180);
    for (int lookat = 1; lookat >= 0; lookat--) {
        s = build(lookat);
        opt_init(&o);
        CHECK(set(&o, opt_set_camera_orthographic, "on"));
        CHECK(look_apply(&o.look, s, &note) == 0);
        const scene_camera *c = &s->camera;
        CHECK(c->kind == SCENE_CAMERA_ORTHOGRAPHIC);
        double up = sqrt(c->up[0] * c->up[0] + c->up[1] * c->up[1] + c->up[2] * c->up[2]);
        double right =
            sqrt(c->right[0] * c->right[0] + c->right[1] * c->right[1] + c->right[2] * c->right[2]);
        double want = 2 * (lookat ? sqrt(58.0) : 5.0) * t22;
        printf("orthographic, %s: view height %.6f (want %.6f)\n",
               lookat ? "gluLookAt" : "no gluLookAt", up, want);
        /* The triangle, drawn without a depth test, is moved toward the
         * camera by the painter's shift (interp_proj.c): 1/20000 nearer. */
        CHECK_NEAR(up, want, lookat ? 1e-6 : want * 1e-4);
        CHECK_NEAR(right / up, 160.0 / 120.0, 1e-6);
        opt_free(&o);
    }

    /* Sizes: one given keeps the aspect; both given keep the vertical view. */
    s = build(1);
    opt_init(&o);
    CHECK(set(&o, opt_set_width, "320"));
    CHECK(look_apply(&o.look, s, &note) == 0);
    CHECK_EQ_U(s->camera.width, 320);
    CHECK_EQ_U(s->camera.height, 240);
    check_cam(&s->camera, &orig, "width 320: same view");
    opt_free(&o);
    s = build(1);
    opt_init(&o);
    CHECK(set(&o, opt_set_width, "240"));
    CHECK(set(&o, opt_set_height, "120"));
    CHECK(look_apply(&o.look, s, &note) == 0);
    CHECK_NEAR(s->camera.right[0], orig.right[0] * 1.5, 1e-9);
    CHECK_NEAR(s->camera.up[1], orig.up[1], 1e-9);
    opt_free(&o);

    /* Bad values. */
    opt_init(&o);
    CHECK(!set(&o, opt_set_light, "sun at=1,2,3"));
    CHECK(!set(&o, opt_set_light, "point"));
    CHECK(!set(&o, opt_set_light, "point at=1,2"));
    CHECK(!set(&o, opt_set_light, "point at=1,2,3 radius=4"));
    CHECK(!set(&o, opt_set_light, "spot at=1,2,3 radius=40 falloff=20"));
    CHECK(!set(&o, opt_set_light, "area at=1,2,3 samples=0,3"));
    CHECK(set(&o, opt_set_light, "area at=1,2,3 size=2,1 samples=3,3"));
    CHECK(!set(&o, opt_set_camera_fov, "180"));
    CHECK(!set(&o, opt_set_camera_up, "0,0,0"));
    CHECK(!set(&o, opt_set_camera_location, "1,2,nan"));
    CHECK(!set(&o, opt_set_width, "0"));
    CHECK(!set(&o, opt_set_quality, "12"));
    opt_free(&o);

    translator_destroy(tr);
    rgl_reader_destroy(reader);
    return CHECK_RESULT("look");
}
