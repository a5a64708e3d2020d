/* relink.c: points the gl* calls of the program, GLU and GLUT at OSMesa
 * when the program's link order sends them to libGL (forward.h).
 *
 * A GLU or GLUT twin forwards to the real gluSphere or glutSolidTeapot,
 * whose gl* calls go through their library's GOT, bound by the dynamic
 * linker to the first library defining each name; so do the program's own
 * gl* calls. With libGL before libOSMesa that is glvnd's dispatch, which
 * draws nothing while the context is OSMesa's. So while the OSMesa table is
 * chosen, their GOT slots for the gl* names RayGL knows hold OSMesa's
 * functions, and the linked ones again afterwards.
 * Done at a context switch only (mprotect on RELRO pages), never per call.
 * The GOT is one per process: with OSMesa and GLX contexts current on two
 * threads at once, the library's shapes follow the last switch.
 */
#include <dlfcn.h>
#include <elf.h>
#include <link.h>
#include <stdint.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#include "relink.h"

#if defined(__x86_64__)
#define RGL_R_SLOT(t) ((t) == R_X86_64_JUMP_SLOT || (t) == R_X86_64_GLOB_DAT)
#elif defined(__aarch64__)
#define RGL_R_SLOT(t) ((t) == R_AARCH64_JUMP_SLOT || (t) == R_AARCH64_GLOB_DAT)
#endif

#if defined(RGL_R_SLOT) && defined(__LP64__)

typedef struct relro {
    uintptr_t base;
    uintptr_t start, end; /* PT_GNU_RELRO of the object, or 0, 0 */
} relro;

static int find_relro(struct dl_phdr_info *info, size_t size, void *arg)
{
    (void)size;
    relro *r = arg;
    if (info->dlpi_addr != r->base)
        return 0;
    for (int i = 0; i < info->dlpi_phnum; i++) {
        const ElfW(Phdr) *ph = &info->dlpi_phdr[i];
        if (ph->p_type == PT_GNU_RELRO) {
            /* As the dynamic linker protects it: whole pages only, so a
             * page the region ends in part-way stays writable. */
            uintptr_t ps = (uintptr_t)sysconf(_SC_PAGESIZE);
            r->start = (r->base + ph->p_vaddr) & ~(ps - 1);
            r->end = (r->base + ph->p_vaddr + ph->p_memsz) & ~(ps - 1);
        }
    }
    return 1;
}

/* A pointer from .dynamic: glibc relocates them on most targets, not all. */
static uintptr_t dyn_ptr(const struct link_map *lm, ElfW(Addr) p)
{
    return p < lm->l_addr ? lm->l_addr + p : p;
}

/* Writes v into slot; makes a RELRO page writable for the time of it. */
static void put_slot(const relro *r, void **slot, void (*fn)(void))
{
    void *v;
    memcpy(&v, &fn, sizeof v);
    if (*slot == v)
        return;
    uintptr_t a = (uintptr_t)slot;
    if (a >= r->start && a < r->end) {
        long ps = sysconf(_SC_PAGESIZE);
        void *page = (void *)(a & ~(uintptr_t)(ps - 1));
        if (mprotect(page, (size_t)ps, PROT_READ | PROT_WRITE) != 0)
            return;
        *slot = v;
        mprotect(page, (size_t)ps, PROT_READ);
    } else {
        *slot = v;
    }
}

static void relink_rela(const struct link_map *lm, const relro *r, const ElfW(Rela) *rel,
                        size_t n, const ElfW(Sym) *sym, const char *str,
                        const char *const *names, void (*const *fns)(void), size_t count)
{
    for (size_t k = 0; k < n; k++) {
        if (!RGL_R_SLOT(ELF64_R_TYPE(rel[k].r_info)))
            continue;
        const ElfW(Sym) *s = &sym[ELF64_R_SYM(rel[k].r_info)];
        const char *nm = str + s->st_name;
        if (s->st_shndx != SHN_UNDEF || nm[0] != 'g' || nm[1] != 'l')
            continue;
        for (size_t i = 0; i < count; i++) {
            if (strcmp(names[i], nm) == 0) {
                put_slot(r, (void **)(lm->l_addr + rel[k].r_offset), fns[i]);
                break;
            }
        }
    }
}

int rgl_relink(void *in_object, const char *const *names, void (*const *fns)(void), size_t count)
{
    Dl_info info;
    struct link_map *lm = NULL;
    if (in_object) {
        if (!dladdr1(in_object, &info, (void **)&lm, RTLD_DL_LINKMAP))
            return -1;
    } else {
        void *h = dlopen(NULL, RTLD_LAZY);
        if (!h)
            return -1;
        if (dlinfo(h, RTLD_DI_LINKMAP, &lm) != 0)
            lm = NULL;
        dlclose(h);
    }
    if (!lm)
        return -1;
    const ElfW(Sym) *sym = NULL;
    const char *str = NULL;
    const ElfW(Rela) *rela = NULL, *jmprel = NULL;
    size_t relasz = 0, pltrelsz = 0;
    int pltrel = 0;
    for (const ElfW(Dyn) *d = lm->l_ld; d->d_tag != DT_NULL; d++) {
        switch (d->d_tag) {
        case DT_SYMTAB: sym = (const ElfW(Sym) *)dyn_ptr(lm, d->d_un.d_ptr); break;
        case DT_STRTAB: str = (const char *)dyn_ptr(lm, d->d_un.d_ptr); break;
        case DT_RELA: rela = (const ElfW(Rela) *)dyn_ptr(lm, d->d_un.d_ptr); break;
        case DT_RELASZ: relasz = d->d_un.d_val; break;
        case DT_JMPREL: jmprel = (const ElfW(Rela) *)dyn_ptr(lm, d->d_un.d_ptr); break;
        case DT_PLTRELSZ: pltrelsz = d->d_un.d_val; break;
        case DT_PLTREL: pltrel = (int)d->d_un.d_val; break;
        default: break;
        }
    }
    if (!sym || !str)
        return -1;
    relro r = {lm->l_addr, 0, 0};
    dl_iterate_phdr(find_relro, &r);
    if (rela)
        relink_rela(lm, &r, rela, relasz / sizeof *rela, sym, str, names, fns, count);
    if (jmprel && pltrel == DT_RELA)
        relink_rela(lm, &r, jmprel, pltrelsz / sizeof *jmprel, sym, str, names, fns, count);
    return 0;
}

#else

int rgl_relink(void *in_object, const char *const *names, void (*const *fns)(void), size_t count)
{
    (void)in_object, (void)names, (void)fns, (void)count;
    return -1;
}

#endif
