/* test_options.c: the option table against its documentation and its parsers.
 *
 *   test_options MANPAGE
 *
 * Every row of options.def appears in the man page's OPTIONS section as
 * "\-\-name" (and "\-x" for its short form); --help names every row; a
 * settings file and the command line set the same fields; settings-file
 * errors name FILE:LINE.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "options.h"

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    char *buf = NULL;
    size_t n = 0, cap = 0;
    int c;
    while ((c = fgetc(f)) != EOF) {
        if (n + 2 > cap) {
            cap = cap ? cap * 2 : 4096;
            buf = realloc(buf, cap);
            if (!buf)
                abort();
        }
        buf[n++] = (char)c;
    }
    fclose(f);
    if (!buf)
        buf = calloc(1, 1);
    else
        buf[n] = '\0';
    return buf;
}

/* "--frames" -> "\-\-frames" as troff spells it. */
static void troff_name(char *out, size_t cap, const char *prefix, const char *name)
{
    size_t k = 0;
    for (const char *p = prefix; *p && k + 3 < cap; p++) {
        if (*p == '-')
            out[k++] = '\\';
        out[k++] = *p;
    }
    for (const char *p = name; *p && k + 3 < cap; p++) {
        if (*p == '-')
            out[k++] = '\\';
        out[k++] = *p;
    }
    out[k] = '\0';
}

/* The word in the man page: not followed by more name characters. */
static bool has_word(const char *text, const char *w)
{
    size_t n = strlen(w);
    for (const char *p = strstr(text, w); p; p = strstr(p + 1, w)) {
        char c = p[n];
        bool more = (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
                    (c == '\\' && p[n + 1] == '-' && p[n + 2] >= 'a' && p[n + 2] <= 'z');
        if (!more)
            return true;
    }
    return false;
}

static char tmpdir[256];

static const char *write_file(const char *name, const char *text)
{
    static char path[512];
    snprintf(path, sizeof path, "%s/%s", tmpdir, name);
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    fputs(text, f);
    fclose(f);
    return path;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: test_options MANPAGE\n");
        return 2;
    }
    char *man = slurp(argv[1]);
    CHECK(man != NULL);
    const char *sec = man ? strstr(man, "\n.SH OPTIONS") : NULL;
    CHECK(sec != NULL);
    const char *end = sec ? strstr(sec + 1, "\n.SH ") : NULL;
    if (end)
        man[end - man] = '\0';

    /* Every option in the man page and in --help. */
    FILE *h = tmpfile();
    CHECK(h != NULL);
    opt_print_help(h, false);
    opt_print_help(h, true);
    long hn = ftell(h);
    rewind(h);
    char *help = calloc(1, (size_t)hn + 1);
    CHECK(help && fread(help, 1, (size_t)hn, h) == (size_t)hn);
    fclose(h);
    size_t missing = 0;
    for (size_t i = 0; i < opt_table_count && sec; i++) {
        const opt_def *d = &opt_table[i];
        char w[128], hw[96];
        troff_name(w, sizeof w, "--", d->name);
        if (!has_word(sec, w)) {
            fprintf(stderr, "FAIL: docs/raygl2pov.1 OPTIONS does not name --%s\n", d->name);
            missing++;
        }
        if (d->short_name) {
            char s[2] = {d->short_name, 0};
            troff_name(w, sizeof w, "-", s);
            if (!has_word(sec, w)) {
                fprintf(stderr, "FAIL: docs/raygl2pov.1 OPTIONS does not name -%c\n",
                        d->short_name);
                missing++;
            }
        }
        snprintf(hw, sizeof hw, "--%s", d->name);
        CHECK(strstr(help, hw) != NULL);
        CHECK(d->help && d->help[0] && d->set);
        for (size_t k = 0; k < i; k++) {
            CHECK(strcmp(opt_table[k].name, d->name) != 0);
            CHECK(!d->short_name || opt_table[k].short_name != d->short_name);
        }
    }
    CHECK(missing == 0);
    printf("%zu options, all in docs/raygl2pov.1 and --help\n", opt_table_count);

    /* The command line and a settings file set the same things. */
    snprintf(tmpdir, sizeof tmpdir, "%s/rgl-opt.XXXXXX", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
    CHECK(mkdtemp(tmpdir) != NULL);
    options a, b;
    opt_err err;
    char *argv_a[] = {"raygl2pov", "t.raygl", "-o", "out", "--frames=1-9:2,20-", "-j3", "-q",
                      NULL};
    opt_init(&a);
    CHECK(opt_parse_args(&a, 7, argv_a, &err));
    const char *conf = write_file("look.conf", "# a look\n"
                                               "output = out   # trailing comment\n"
                                               "--frames 1-9:2,20-\n"
                                               "\n"
                                               "jobs=3\n"
                                               "quiet = on\n");
    opt_init(&b);
    b.trace = "t.raygl";
    CHECK(opt_parse_file(&b, conf, &err));
    CHECK(strcmp(a.trace, b.trace) == 0);
    CHECK(strcmp(a.outdir, "out") == 0);
    /* Relative paths in a settings file are taken from its folder. */
    char want[600];
    snprintf(want, sizeof want, "%s/out", tmpdir);
    CHECK(b.outdir && strcmp(b.outdir, want) == 0);
    CHECK(a.nranges == 2 && b.nranges == 2);
    CHECK(memcmp(a.ranges, b.ranges, 2 * sizeof *a.ranges) == 0);
    CHECK(a.jobs == 3 && b.jobs == 3 && a.quiet && b.quiet);
    /* Steps select every STEP-th frame from the range's first. */
    CHECK(opt_frame_selected(&a, 1) && opt_frame_selected(&a, 9) && !opt_frame_selected(&a, 2));
    CHECK(opt_frame_selected(&a, 20) && opt_frame_selected(&a, 1000) && !opt_frame_selected(&a, 10));
    opt_free(&a);
    opt_free(&b);

    /* Errors name the file and line. */
    static const struct {
        const char *text, *msg;
    } bad[] = {
        {"quiet\n\nbogus = 1\n", ":3: unknown option 'bogus'"},
        {"# x\nframes = 5-2\n", ":2: frames '5-2': range 5-2 runs backwards"},
        {"jobs\n", ":1: 'jobs' needs a value"},
        {"help\n", ":1: 'help' is a command-line option"},
        {"quiet = maybe\n", ":1: quiet 'maybe': expected on or off"},
        {"settings = look.conf\n",
         ":1: settings 'look.conf': that settings file is already being read (a cycle)"},
        {"light = \"1,2\n", ":1: unterminated quote"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        const char *p = write_file("look.conf", bad[i].text);
        opt_init(&b);
        bool ok = opt_parse_file(&b, p, &err);
        CHECK(!ok);
        if (!ok && (strncmp(err.msg, p, strlen(p)) != 0 || !strstr(err.msg, bad[i].msg))) {
            fprintf(stderr, "FAIL: settings error '%s', expected '%s%s'\n", err.msg, p,
                    bad[i].msg);
            check_failures++;
        }
        opt_free(&b);
    }
    char rm[600];
    snprintf(rm, sizeof rm, "%s/look.conf", tmpdir);
    remove(rm);
    remove(tmpdir);
    free(help);
    free(man);
    return CHECK_RESULT("options");
}
