/* naming.c: output file names (naming.h). */
#include "naming.h"

#include <stdbool.h>
#include <stdio.h>
#include <string.h>

void name_sanitize(const char *name, char *out, size_t cap)
{
    const char *base = name;
    for (const char *p = name; *p; p++)
        if (*p == '/' || *p == '\\')
            base = p + 1;
    size_t n = strlen(base);
    if (n >= 4 && strcmp(base + n - 4, ".pov") == 0)
        n -= 4;
    size_t k = 0;
    for (size_t i = 0; i < n && k + 1 < cap && k < NAME_MAX_STEM; i++) {
        char c = base[i];
        bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                  c == '_' || c == '-' || c == '.';
        out[k++] = ok ? c : '_';
    }
    out[k] = '\0';
    if (out[0] == '.')
        out[0] = '_';
}

/* A placeholder at p ("{index:5}"): its expansion into buf; returns the
 * length of the placeholder, 0 when it is not one. */
static size_t placeholder(const char *p, const name_vars *v, char *buf, size_t cap)
{
    static const char *const keys[] = {"index", "stream", "number", "name", "trace"};
    if (*p != '{')
        return 0;
    const char *close = strchr(p, '}');
    if (!close)
        return 0;
    for (int k = 0; k < 5; k++) {
        size_t kl = strlen(keys[k]);
        if (strncmp(p + 1, keys[k], kl) != 0)
            continue;
        const char *q = p + 1 + kl;
        int width = 0;
        if (*q == ':' && k <= 2) {
            q++;
            if (*q < '1' || *q > '9' || (q[1] != '}' && (q[1] < '0' || q[1] > '9' || q[2] != '}')))
                return 0;
            width = *q - '0';
            if (q[1] != '}')
                width = width * 10 + (q[1] - '0');
            if (width > 20)
                return 0;
            q += q[1] == '}' ? 1 : 2;
        }
        if (q != close)
            return 0;
        if (!v) {
            buf[0] = '\0';
        } else if (k <= 2) {
            unsigned long long n = k == 0 ? v->index : k == 1 ? v->stream : v->number;
            snprintf(buf, cap, "%0*llu", width, n);
        } else if (k == 3) {
            char s[NAME_MAX_STEM + 1];
            name_sanitize(v->frame_name ? v->frame_name : "", s, sizeof s);
            snprintf(buf, cap, "%s", s[0] ? s : "frame");
        } else {
            char s[NAME_MAX_STEM + 1];
            name_sanitize(v->trace ? v->trace : "", s, sizeof s);
            size_t n = strlen(s);
            if (n > 6 && strcmp(s + n - 6, ".raygl") == 0)
                s[n - 6] = '\0';
            snprintf(buf, cap, "%s", s[0] ? s : "trace");
        }
        return (size_t)(close - p) + 1;
    }
    return 0;
}

void name_stem(const char *pattern, const name_vars *v, char *out, size_t cap)
{
    char raw[4 * NAME_MAX_STEM];
    out[0] = '\0';
    if (pattern) {
        size_t k = 0;
        for (const char *p = pattern; *p && k + 1 < sizeof raw;) {
            char buf[NAME_MAX_STEM + 32];
            size_t n = placeholder(p, v, buf, sizeof buf);
            if (n) {
                size_t bl = strlen(buf);
                if (k + bl >= sizeof raw)
                    break;
                memcpy(raw + k, buf, bl);
                k += bl;
                p += n;
            } else {
                raw[k++] = *p++;
            }
        }
        raw[k] = '\0';
        /* The whole expansion is one file name: a '/' in it is replaced. */
        for (char *p = raw; *p; p++)
            if (*p == '/' || *p == '\\')
                *p = '_';
        name_sanitize(raw, out, cap);
    } else if (v->frame_name) {
        name_sanitize(v->frame_name, out, cap);
    }
    if (!out[0])
        snprintf(out, cap, "frame-%05llu", (unsigned long long)v->index);
}

bool name_is_placeholder(const char *p)
{
    char buf[8];
    return placeholder(p, NULL, buf, sizeof buf) != 0;
}
