/* outbuf.c: the buffered text sink (outbuf.h). */
#include "outbuf.h"

#include "talloc.h"

int outbuf_init(outbuf *ob, size_t cap, int (*flush)(void *user, const char *data, size_t n),
                void *user)
{
    memset(ob, 0, sizeof *ob);
    if (cap < 256)
        cap = 256;
    ob->buf = tr_realloc(NULL, cap);
    if (!ob->buf) {
        ob->failed = true;
        return -1;
    }
    ob->cap = cap;
    ob->flush = flush;
    ob->user = user;
    return 0;
}

void outbuf_finish(outbuf *ob)
{
    tr_free(ob->buf);
    ob->buf = NULL;
    ob->len = ob->cap = 0;
}

int outbuf_flush(outbuf *ob)
{
    if (ob->failed)
        return -1;
    if (!ob->flush || ob->len == 0)
        return 0;
    if (ob->flush(ob->user, ob->buf, ob->len) != 0) {
        ob->failed = true;
        return -1;
    }
    ob->len = 0;
    return 0;
}

char *outbuf_room_slow(outbuf *ob, size_t n)
{
    if (ob->failed)
        return NULL;
    if (ob->flush) {
        if (outbuf_flush(ob) != 0)
            return NULL;
        if (ob->cap >= n)
            return ob->buf;
    }
    if (tr_grow((void **)&ob->buf, &ob->cap, ob->len + n, 1) != 0) {
        ob->failed = true;
        return NULL;
    }
    return ob->buf + ob->len;
}

void outbuf_write(outbuf *ob, const char *s, size_t n)
{
    while (n > 0 && !ob->failed) {
        size_t room = ob->cap - ob->len;
        if (room == 0) {
            if (!outbuf_room_slow(ob, n < 4096 ? n : 4096))
                return;
            continue;
        }
        size_t k = n < room ? n : room;
        memcpy(ob->buf + ob->len, s, k);
        outbuf_commit(ob, k);
        s += k;
        n -= k;
    }
}
