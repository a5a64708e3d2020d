/* povwrite_look.c: what the look step put into the scene beyond GL's
 * picture, in POV-Ray's terms (povwrite_look.h): radiosity, the added
 * lights, the user's include files and the render settings of the .ini.
 */
#include "povwrite_look.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "talloc.h"
#include "writer.h"

static void put_vec(outbuf *ob, const double v[3])
{
    outbuf_putc(ob, '<');
    for (int k = 0; k < 3; k++) {
        if (k)
            outbuf_putc(ob, ',');
        outbuf_f32(ob, isfinite(v[k]) ? (float)v[k] : 0.0f);
    }
    outbuf_putc(ob, '>');
}

static void put_added_light(outbuf *ob, const scene_light *l)
{
    double colour[3] = {l->color[0], l->color[1], l->color[2]};
    outbuf_puts(ob, "light_source{");
    put_vec(ob, l->position);
    outbuf_puts(ob, " rgb");
    put_vec(ob, colour);
    if (l->kind == SCENE_LIGHT_PARALLEL) {
        outbuf_puts(ob, " parallel point_at");
        put_vec(ob, l->point_at);
    } else if (l->kind == SCENE_LIGHT_SPOT) {
        outbuf_puts(ob, " spotlight point_at");
        put_vec(ob, l->point_at);
        outbuf_puts(ob, " radius ");
        outbuf_f32(ob, l->spot_radius);
        outbuf_puts(ob, " falloff ");
        outbuf_f32(ob, l->spot_cutoff);
    } else if (l->area_samples[0] > 0) {
        outbuf_puts(ob, " area_light ");
        put_vec(ob, l->area_axis[0]);
        outbuf_putc(ob, ',');
        put_vec(ob, l->area_axis[1]);
        outbuf_putc(ob, ',');
        outbuf_u64(ob, (uint64_t)l->area_samples[0]);
        outbuf_putc(ob, ',');
        outbuf_u64(ob, (uint64_t)l->area_samples[1]);
        outbuf_puts(ob, " adaptive 1 jitter circular orient");
    }
    outbuf_puts(ob, "}\n");
}

void povlook_scene(outbuf *ob, const scene *s)
{
    if (s->options.radiosity)
        outbuf_puts(ob, "// --radiosity\nglobal_settings{radiosity{}}\n");
    bool any = false;
    for (size_t i = 0; i < s->nlights; i++) {
        if (!s->lights[i].added)
            continue;
        if (!any)
            outbuf_puts(ob, s->options.world_view ? "// --light, given in world coordinates\n"
                                                  : "// --light, given in eye coordinates\n");
        any = true;
        put_added_light(ob, &s->lights[i]);
    }
}

void povlook_includes(outbuf *ob, const scene *s, const char *const *names, size_t n)
{
    if (!n)
        return;
    /* World -> eye for the user's SDL: the scene is in eye coordinates. */
    bool world = s->options.world_view;
    outbuf_puts(ob, "// --include: RayGL_World takes world coordinates (after the frame's\n"
                    "// gluLookAt) to the scene's eye coordinates; identity without one.\n"
                    "#declare RayGL_World = transform{matrix<");
    for (int c = 0; c < 4; c++)
        for (int r = 0; r < 3; r++) {
            double m = world ? s->view.m[c * 4 + r] : (c == r ? 1 : 0);
            outbuf_f32(ob, isfinite(m) ? (float)m : 0.0f);
            if (c * 3 + r < 11)
                outbuf_putc(ob, ',');
        }
    outbuf_puts(ob, ">}\n");
    if (n)
        /* POV-Ray's own default finish again (its manual's ambient 0.1,
         * diffuse 0.6, no emission): the scene's unlit default (povwrite.c)
         * is RayGL's, and would make the user's objects flat and unlit. */
        outbuf_puts(ob, "#default{finish{ambient 0.1 diffuse 0.6 emission 0}}\n");
    for (size_t i = 0; i < n; i++) {
        /* Names are [A-Za-z0-9._-] (povlook_copy_includes): nothing to escape. */
        outbuf_puts(ob, "#include \"");
        outbuf_puts(ob, names[i]);
        outbuf_puts(ob, "\"\n");
    }
}

void povlook_ini(outbuf *ob, const scene_options *o)
{
    if (o->antialias)
        outbuf_puts(ob, "; --antialias\nAntialias=On\nAntialias_Threshold=0.3\n");
    if (o->quality) {
        outbuf_puts(ob, "; --quality\nQuality=");
        outbuf_u64(ob, o->quality < 0 ? 0 : (uint64_t)o->quality);
        outbuf_putc(ob, '\n');
    }
}

/* ---- Include files --------------------------------------------------------------------- */

void povlook_free_names(char **names, size_t n)
{
    for (size_t i = 0; names && i < n; i++)
        tr_free(names[i]);
    tr_free(names);
}

/* An unchanged copy keeps its time: rendered frames stay up to date. */
static int copy_file(const char *from, const char *to, char *msg, size_t cap)
{
    if (writer_files_same(from, to))
        return 0;
    char tmp[4200];
    snprintf(tmp, sizeof tmp, "%s.%ld.tmp", to, (long)getpid());
    int in = open(from, O_RDONLY | O_CLOEXEC);
    if (in < 0) {
        snprintf(msg, cap, "%s: cannot read: %s", from, strerror(errno));
        return -1;
    }
    int out = open(tmp, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (out < 0) {
        snprintf(msg, cap, "%s: cannot create: %s", tmp, strerror(errno));
        close(in);
        return -1;
    }
    char buf[65536];
    ssize_t n;
    int rc = 0, e = 0;
    while ((n = read(in, buf, sizeof buf)) != 0) {
        if (n < 0) {
            if (errno == EINTR)
                continue;
            rc = -1, e = errno;
            break;
        }
        for (ssize_t off = 0; off < n;) {
            ssize_t w = write(out, buf + off, (size_t)(n - off));
            if (w < 0 && errno == EINTR)
                continue;
            if (w < 0) {
                rc = -1, e = errno;
                break;
            }
            off += w;
        }
        if (rc)
            break;
    }
    close(in);
    if (close(out) != 0 && rc == 0)
        rc = -1, e = errno;
    if (rc == 0 && rename(tmp, to) != 0)
        rc = -1, e = errno;
    if (rc != 0) {
        unlink(tmp);
        snprintf(msg, cap, "%s: cannot copy to %s: %s", from, to, strerror(e));
    }
    return rc;
}

int povlook_copy_includes(const char *const *paths, size_t n, const char *dir, char ***names,
                          char *msg, size_t cap)
{
    *names = NULL;
    if (!n)
        return 0;
    char **v = tr_realloc(NULL, n * sizeof *v);
    if (!v) {
        snprintf(msg, cap, "out of memory");
        return -1;
    }
    memset(v, 0, n * sizeof *v);
    for (size_t i = 0; i < n; i++) {
        const char *base = strrchr(paths[i], '/');
        base = base ? base + 1 : paths[i];
        char name[160];
        int k = snprintf(name, sizeof name, "include-%zu-", i + 1);
        for (const char *p = base; *p && k + 1 < (int)sizeof name; p++) {
            char c = *p;
            bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                      (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '.';
            name[k++] = ok ? c : '_';
        }
        name[k] = '\0';
        size_t dl = strlen(dir);
        char *path = tr_realloc(NULL, dl + strlen(name) + 2);
        v[i] = tr_realloc(NULL, strlen(name) + 1);
        if (!path || !v[i]) {
            tr_free(path);
            povlook_free_names(v, n);
            snprintf(msg, cap, "out of memory");
            return -1;
        }
        strcpy(v[i], name);
        sprintf(path, "%s%s%s", dir, dl && dir[dl - 1] == '/' ? "" : "/", name);
        int rc = copy_file(paths[i], path, msg, cap);
        tr_free(path);
        if (rc != 0) {
            povlook_free_names(v, n);
            return -1;
        }
    }
    *names = v;
    return 0;
}
