/* Grader machinery: not part of any assignment.
 * The object inspection (grade_inspect.h): before any of a submission's code is linked or run, the
 * objects the build made from its part (the very files linked into bin/pathtracer and the split
 * suite's subject: graded trees build without link-time optimisation, so they hold machine code)
 * are read as data through libelf, and everything in them must be on a list:
 *
 * - sections: the kinds plain C compiles to, by type and name (code in .text*, data in .data*,
 *   .rodata*, .bss*, thread-local data in .tdata* and .tbss*, notes, unwind tables, debug
 *   information, the symbol and string tables and relocations); only code sections executable.
 *   Anything else is refused, the sections the C runtime runs code from first among them
 *   (.init_array, .fini_array, .preinit_array, .ctors, .dtors, .init, .fini, and the
 *   transactional-memory clone table, .tm_clone_table, that crtbegin registers);
 * - symbols: of the types and bindings plain C makes (no IFUNC, whose resolver the loader runs
 *   before main; no GNU unique binding); a global definition's name must not be reserved to the C
 *   implementation (a leading underscore, or main: the names the runtime and the loader call, such as
 *   _init, __gmon_start__ and _ITM_registerTMCloneTable, are all reserved ones), nor a name a
 *   library of the program defines (malloc would replace the allocator for the whole program), nor
 *   one the framework or another part defines;
 * - references: every undefined symbol must be on the allow-list (grade_allow.c) or a global
 *   definition of the part's own objects. A local (static) definition never counts: a reference to
 *   `open` in one file is the C library's open whatever another file defines static.
 * Any bound reached (sections, symbols, a name's length) refuses the object, and every step is
 * linear in its size (names are looked up in hash sets, grade_names.c).
 *
 * This is defence in depth and hygiene; what confines student code is the sandbox (the filter is
 * installed before its first instruction, grade_run.c), so the inspection claims no more than it
 * checks: it does not read the machine code (a disassembler can be led astray by instructions that
 * overlap), and the filter stops a system call however it is made. */
#include "grade_inspect.h"
#include "grade_allow.h"
#include "grade_why.h"
#include "grade_plan.h"
#include "grade_run.h"
#include "../framework/file.h"
#include "../framework/seam.h"
#include <dirent.h>
#include <fcntl.h>
#ifdef PL_HAVE_LIBELF
#include <gelf.h>
#include <libelf.h>
#endif
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* ---- names of sections ------------------------------------------------------------------------- */

/* Whether name is prefix itself or prefix followed by "." and more (".text" and ".text.startup"). */
static bool named(const char *name, const char *prefix)
{
    size_t n = strlen(prefix);
    return !strncmp(name, prefix, n) && (name[n] == '\0' || name[n] == '.');
}

static bool starts(const char *name, const char *prefix) { return !strncmp(name, prefix, strlen(prefix)); }

/* The sections the C runtime or the loader runs code from, or calls through: never allowed, and
 * named in the message (their names are the runtime's, not the student's). */
static const char *const before_main[] = {".init_array", ".fini_array", ".preinit_array", ".ctors", ".dtors",
                                          ".init", ".fini", ".tm_clone_table", ".jcr", NULL};

static const char *runtime_section(const char *name)
{
    for (const char *const *s = before_main; *s; s++)
        if (named(name, *s)) return *s;
    return NULL;
}

#ifdef PL_HAVE_LIBELF

/* ---- the course's names: from trusted files only ---------------------------------------------- */

/* The ELF handle of a file, or NULL (the caller closes fd). */
static Elf *elf_open(const char *path, int *fd)
{
    *fd = open(path, O_RDONLY | O_CLOEXEC);
    if (*fd < 0 || elf_version(EV_CURRENT) == EV_NONE) return NULL;
    Elf *e = elf_begin(*fd, ELF_C_READ, NULL);
    if (e && elf_kind(e) != ELF_K_ELF) elf_end(e), e = NULL;
    return e;
}

static void elf_close(Elf *e, int fd)
{
    if (e) elf_end(e);
    if (fd >= 0) close(fd);
}

/* The first section of type `type`, with its header; NULL when there is none. */
static Elf_Scn *section_of_type(Elf *e, Elf64_Word type, GElf_Shdr *sh)
{
    for (Elf_Scn *s = elf_nextscn(e, NULL); s; s = elf_nextscn(e, s))
        if (gelf_getshdr(s, sh) && sh->sh_type == type) return s;
    return NULL;
}

/* Adds every defined global or weak symbol of the table of `type` (SHT_SYMTAB or SHT_DYNSYM) in e. */
static bool add_defined(Elf *e, Elf64_Word type, grade_names *set)
{
    GElf_Shdr sh;
    Elf_Scn *s = section_of_type(e, type, &sh);
    Elf_Data *d = s ? elf_getdata(s, NULL) : NULL;
    if (!d || sh.sh_entsize == 0) return s == NULL;
    size_t n = sh.sh_size / sh.sh_entsize;
    for (size_t i = 1; i < n; i++) {
        GElf_Sym sym;
        const char *name;
        if (!gelf_getsym(d, (int)i, &sym) || sym.st_shndx == SHN_UNDEF || GELF_ST_BIND(sym.st_info) == STB_LOCAL) continue;
        if ((name = elf_strptr(e, sh.sh_link, sym.st_name)) && *name && !grade_names_add(set, name)) return false;
    }
    return true;
}

/* A library the program needs, found as the linker would: the compiler's search path. */
static bool library_path(const char *name, char *out, size_t size)
{
    char cmd[512];
    if (strpbrk(name, "'\"\\$`\n ") || snprintf(cmd, sizeof cmd, "cc -print-file-name='%s' 2>/dev/null", name) >= (int)sizeof cmd)
        return false;
    FILE *p = popen(cmd, "r");
    bool ok = p && fgets(out, (int)size, p) != NULL;
    if (p) pclose(p);
    out[strcspn(out, "\n")] = '\0';
    return ok && out[0] == '/' && access(out, R_OK) == 0;
}

/* The names the program's NEEDED libraries define, and theirs in turn, breadth first: transitive
 * ones count (a part that defined lzma_code would run its code inside the scene loader). */
static bool add_libraries(Elf *program, grade_names *library)
{
    enum { MAX_LIBS = 64 };
    char queue[MAX_LIBS][256];
    int queued = 0;
    grade_names seen = {0};
    bool ok = true;
    for (int next = -1; ok && next < queued; next++) {
        int fd = -1;
        char path[4096];
        Elf *e = next < 0 ? program : library_path(queue[next], path, sizeof path) ? elf_open(path, &fd) : NULL;
        GElf_Shdr sh;
        Elf_Scn *dyn = e ? section_of_type(e, SHT_DYNAMIC, &sh) : NULL;
        Elf_Data *d = dyn ? elf_getdata(dyn, NULL) : NULL;
        for (size_t i = 0; d && sh.sh_entsize && i < sh.sh_size / sh.sh_entsize; i++) {
            GElf_Dyn entry;
            const char *name;
            if (!gelf_getdyn(d, (int)i, &entry) || entry.d_tag != DT_NEEDED) continue;
            if (!(name = elf_strptr(e, sh.sh_link, entry.d_un.d_val)) || grade_names_has(&seen, name)) continue;
            if (queued == MAX_LIBS || strlen(name) >= sizeof queue[0] || !grade_names_add(&seen, name)) ok = false;
            else snprintf(queue[queued++], sizeof queue[0], "%s", name);
        }
        if (e && next >= 0) ok = ok && add_defined(e, SHT_DYNSYM, library);
        if (next >= 0) elf_close(e, fd);
    }
    grade_names_free(&seen);
    return ok;
}

bool grade_inspect_course_load(const char *program, const char *const *own_objects, grade_inspect_course *c,
                               char *why, size_t size)
{
    *c = (grade_inspect_course){0};
    bool ok = grade_allow_add_all(&c->allowed);
#define ADD_PART_FUNCTION(name, task) ok = ok && grade_names_add(&c->allowed, #name);
    PL_SEAM_PART_FUNCTIONS(ADD_PART_FUNCTION)
#undef ADD_PART_FUNCTION
    int fd = -1;
    Elf *e = ok ? elf_open(program, &fd) : NULL;
    GElf_Ehdr eh;
    ok = e && gelf_getehdr(e, &eh) && add_defined(e, SHT_SYMTAB, &c->program) && add_libraries(e, &c->library);
    if (ok) c->machine = eh.e_machine;
    elf_close(e, fd);
    /* The part's own names are not the program's to keep: the course's part defines them too. */
    grade_names own = {0}, without = {0};
    for (const char *const *o = own_objects; ok && o && *o; o++) {
        Elf *oe = elf_open(*o, &fd);
        ok = oe && add_defined(oe, SHT_SYMTAB, &own);
        elf_close(oe, fd);
    }
    for (size_t k = 0; ok && own.count && k < c->program.capacity; k++)  /* the set has no removal */
        if (c->program.slots[k] && !grade_names_has(&own, c->program.slots[k]))
            ok = grade_names_add(&without, c->program.slots[k]);
    if (ok && own.count) {
        grade_names_free(&c->program);
        c->program = without;
    }
    else grade_names_free(&without);
    grade_names_free(&own);
    if (!ok) {
        grade_inspect_course_free(c);
        grade_msg(why, size, "cannot read the names of the course's program %s or of its libraries", program);
    }
    return ok;
}

void grade_inspect_course_free(grade_inspect_course *c)
{
    if (!c) return;
    grade_names_free(&c->allowed);
    grade_names_free(&c->library);
    grade_names_free(&c->program);
}

/* ---- sections: by kind ------------------------------------------------------------------------ */

#ifndef SHT_X86_64_UNWIND
#define SHT_X86_64_UNWIND 0x70000001
#endif
#ifndef SHT_LLVM_ADDRSIG
#define SHT_LLVM_ADDRSIG 0x6fff4c03
#endif
#ifndef SHF_GNU_RETAIN
#define SHF_GNU_RETAIN 0x200000
#endif
/* The flags plain C's sections carry (SHF_EXCLUDE, which marks link-time bytecode, is not one). */
#define PLAIN_FLAGS (SHF_WRITE | SHF_ALLOC | SHF_EXECINSTR | SHF_MERGE | SHF_STRINGS | SHF_INFO_LINK | SHF_LINK_ORDER | \
                     SHF_GROUP | SHF_TLS | SHF_COMPRESSED | SHF_GNU_RETAIN)

/* A section's verdict: OK, or the code that refuses it. */
static int section_kind(const GElf_Shdr *sh, const char *name)
{
    if (runtime_section(name) || sh->sh_type == SHT_INIT_ARRAY || sh->sh_type == SHT_FINI_ARRAY ||
        sh->sh_type == SHT_PREINIT_ARRAY)
        return GRADE_INSPECT_BEFORE_MAIN;
    if (starts(name, ".gnu.lto_") || starts(name, ".gnu.debuglto_") || starts(name, ".llvm.lto") || !strcmp(name, ".llvmbc"))
        return GRADE_INSPECT_BYTECODE;
    /* Clang's address-significance table (the symbols whose address is taken, read by the linker
     * to fold identical code safely) is marked SHF_EXCLUDE and nothing else: data for the linker,
     * never part of a program. That table, with exactly that flag, is the one use of it let through. */
    if (sh->sh_type == SHT_LLVM_ADDRSIG)
        return !strcmp(name, ".llvm_addrsig") && sh->sh_flags == SHF_EXCLUDE ? GRADE_INSPECT_OK : GRADE_INSPECT_SECTION;
    if (sh->sh_flags & ~(GElf_Xword)PLAIN_FLAGS) return GRADE_INSPECT_SECTION;
    bool code = named(name, ".text");
    if ((sh->sh_flags & SHF_EXECINSTR) && (!code || (sh->sh_flags & SHF_WRITE))) return GRADE_INSPECT_SECTION;
    if ((sh->sh_flags & SHF_TLS) && !named(name, ".tdata") && !named(name, ".tbss")) return GRADE_INSPECT_SECTION;
    bool ok;
    switch (sh->sh_type) {
    case SHT_PROGBITS:
        ok = code || named(name, ".rodata") || named(name, ".data") || named(name, ".tdata") || !strcmp(name, ".comment") ||
             !strcmp(name, ".note.GNU-stack") || starts(name, ".debug_") || !strcmp(name, ".eh_frame");
        break;
    case SHT_NOBITS: ok = named(name, ".bss") || named(name, ".tbss"); break;
    case SHT_NOTE: ok = starts(name, ".note."); break;
    case SHT_RELA: ok = starts(name, ".rela."); break;
    case SHT_REL: ok = starts(name, ".rel."); break;
    case SHT_SYMTAB: ok = !strcmp(name, ".symtab"); break;
    case SHT_SYMTAB_SHNDX: ok = !strcmp(name, ".symtab_shndx"); break;
    case SHT_STRTAB: ok = !strcmp(name, ".strtab") || !strcmp(name, ".shstrtab"); break;
    case SHT_GROUP: ok = !strcmp(name, ".group"); break;
    case SHT_X86_64_UNWIND: ok = !strcmp(name, ".eh_frame"); break;
    default: ok = false;
    }
    return ok ? GRADE_INSPECT_OK : GRADE_INSPECT_SECTION;
}

/* ---- symbols: by type, binding and name -------------------------------------------------------- */

#ifndef STT_GNU_IFUNC
#define STT_GNU_IFUNC 10
#endif

/* A global name reserved to the C implementation (C11 7.1.3: a leading underscore at file scope),
 * or main: every name the C runtime or the loader calls a program by is one of these. */
static bool reserved(const char *name)
{
    return name[0] == '_' || !strcmp(name, "main");
}

/* One object being inspected: its handle, its sections' verdicts, and what it refers to. */
typedef struct {
    Elf *e;
    size_t sections;            /* how many */
    size_t symtab_link;         /* the string table of .symtab */
} object;

static grade_inspect_verdict verdict_of(int code, int object_index, const char *name, long bound)
{
    grade_inspect_verdict v = {.code = code, .object = object_index, .bound = bound};
    if (name) snprintf(v.name, sizeof v.name, "%s", name);
    return v;
}

/* Every section of o against the kinds above. */
static grade_inspect_verdict check_sections(object *o, int index)
{
    size_t names;
    if (elf_getshdrnum(o->e, &o->sections) != 0 || elf_getshdrstrndx(o->e, &names) != 0)
        return verdict_of(GRADE_INSPECT_UNREADABLE, index, NULL, 0);
    if (o->sections > GRADE_INSPECT_SECTIONS) return verdict_of(GRADE_INSPECT_BOUND, index, "sections", GRADE_INSPECT_SECTIONS);
    for (Elf_Scn *s = elf_nextscn(o->e, NULL); s; s = elf_nextscn(o->e, s)) {
        GElf_Shdr sh;
        const char *name = gelf_getshdr(s, &sh) ? elf_strptr(o->e, names, sh.sh_name) : NULL;
        if (!name) return verdict_of(GRADE_INSPECT_UNREADABLE, index, NULL, 0);
        if (strlen(name) > GRADE_INSPECT_NAME_BYTES)
            return verdict_of(GRADE_INSPECT_BOUND, index, "a section's name", GRADE_INSPECT_NAME_BYTES);
        int kind = section_kind(&sh, name);
        if (kind != GRADE_INSPECT_OK) return verdict_of(kind, index, name, 0);
    }
    return verdict_of(GRADE_INSPECT_OK, index, NULL, 0);
}

/* One symbol's type, binding and section (defined ones into sections that exist, absolute values
 * only for the local file names compilers write). */
static int symbol_kind(const GElf_Sym *sym, const object *o)
{
    int type = GELF_ST_TYPE(sym->st_info), bind = GELF_ST_BIND(sym->st_info);
    if (type == STT_GNU_IFUNC) return GRADE_INSPECT_IFUNC;
    if (type != STT_NOTYPE && type != STT_OBJECT && type != STT_FUNC && type != STT_SECTION && type != STT_FILE &&
        type != STT_COMMON && type != STT_TLS)
        return GRADE_INSPECT_SYMBOL_KIND;
    if (bind != STB_LOCAL && bind != STB_GLOBAL && bind != STB_WEAK) return GRADE_INSPECT_SYMBOL_KIND;
    if (sym->st_shndx == SHN_ABS && bind != STB_LOCAL) return GRADE_INSPECT_SYMBOL_KIND;
    if (sym->st_shndx != SHN_UNDEF && sym->st_shndx != SHN_ABS && sym->st_shndx != SHN_COMMON &&
        sym->st_shndx != SHN_XINDEX && sym->st_shndx >= o->sections)
        return GRADE_INSPECT_SYMBOL_KIND;
    return GRADE_INSPECT_OK;
}

/* A list of the names an object refers to, checked once every object's definitions are known. */
typedef struct {
    char **names;
    int *objects;
    size_t count, capacity;
} reference_list;

static bool reference_add(reference_list *l, const char *name, int index)
{
    if (l->count == l->capacity) {
        size_t capacity = l->capacity ? 2 * l->capacity : 256;
        char **names = realloc(l->names, capacity * sizeof *names);
        if (names) l->names = names;
        int *objects = realloc(l->objects, capacity * sizeof *objects);
        if (objects) l->objects = objects;
        if (!names || !objects) return false;
        l->capacity = capacity;
    }
    l->objects[l->count] = index;
    return (l->names[l->count++] = strdup(name)) != NULL;
}

static void reference_free(reference_list *l)
{
    for (size_t i = 0; i < l->count; i++) free(l->names[i]);
    free(l->names);
    free(l->objects);
}

/* Every symbol of o: its kind, its definitions' names (added to own), its references (to refs). */
static grade_inspect_verdict check_symbols(object *o, int index, const grade_inspect_course *c, grade_names *own,
                                           reference_list *refs)
{
    GElf_Shdr sh;
    Elf_Scn *s = section_of_type(o->e, SHT_SYMTAB, &sh);
    Elf_Data *d = s ? elf_getdata(s, NULL) : NULL;
    if (!s) return verdict_of(GRADE_INSPECT_OK, index, NULL, 0);  /* an empty file's object */
    if (!d || sh.sh_entsize == 0) return verdict_of(GRADE_INSPECT_UNREADABLE, index, NULL, 0);
    size_t n = sh.sh_size / sh.sh_entsize;
    if (n > GRADE_INSPECT_SYMBOLS) return verdict_of(GRADE_INSPECT_BOUND, index, "symbols", GRADE_INSPECT_SYMBOLS);
    for (size_t i = 1; i < n; i++) {
        GElf_Sym sym;
        const char *name = gelf_getsym(d, (int)i, &sym) ? elf_strptr(o->e, sh.sh_link, sym.st_name) : NULL;
        if (!name) return verdict_of(GRADE_INSPECT_UNREADABLE, index, NULL, 0);
        if (strlen(name) > GRADE_INSPECT_NAME_BYTES)
            return verdict_of(GRADE_INSPECT_BOUND, index, "a symbol's name", GRADE_INSPECT_NAME_BYTES);
        int kind = symbol_kind(&sym, o);
        if (kind != GRADE_INSPECT_OK) return verdict_of(kind, index, name, 0);
        if (GELF_ST_BIND(sym.st_info) == STB_LOCAL || !*name) continue;  /* a local name is the file's alone */
        if (sym.st_shndx == SHN_UNDEF) {
            if (!reference_add(refs, name, index)) return verdict_of(GRADE_INSPECT_BOUND, index, "memory", 0);
            continue;
        }
        if (reserved(name)) return verdict_of(GRADE_INSPECT_RESERVED, index, name, 0);
        if (grade_names_has(&c->library, name) || grade_names_has(&c->program, name))
            return verdict_of(GRADE_INSPECT_REDEFINES, index, name, 0);
        if (!grade_names_add(own, name)) return verdict_of(GRADE_INSPECT_BOUND, index, "memory", 0);
    }
    return verdict_of(GRADE_INSPECT_OK, index, NULL, 0);
}

/* One object: readable as a relocatable ELF object of the course's machine, then its sections and
 * symbols. */
static grade_inspect_verdict check_object(const char *path, int index, const grade_inspect_course *c, grade_names *own,
                                          reference_list *refs)
{
    int fd = -1;
    object o = {elf_open(path, &fd), 0, 0};
    GElf_Ehdr eh;
    grade_inspect_verdict v = verdict_of(GRADE_INSPECT_UNREADABLE, index, NULL, 0);
    if (o.e && gelf_getehdr(o.e, &eh) && eh.e_type == ET_REL && eh.e_machine == c->machine) {
        v = check_sections(&o, index);
        if (v.code == GRADE_INSPECT_OK) v = check_symbols(&o, index, c, own, refs);
    }
    elf_close(o.e, fd);
    return v;
}

grade_inspect_verdict grade_inspect_objects(const char *const objects[], int n, const grade_inspect_course *c)
{
    grade_names own = {0};
    reference_list refs = {0};
    grade_inspect_verdict v = verdict_of(GRADE_INSPECT_OK, 0, NULL, 0);
    for (int i = 0; i < n && v.code == GRADE_INSPECT_OK; i++) v = check_object(objects[i], i, c, &own, &refs);
    /* References last: a global of any of the part's files may be called from the others. */
    for (size_t i = 0; i < refs.count && v.code == GRADE_INSPECT_OK; i++)
        if (!grade_names_has(&c->allowed, refs.names[i]) && !grade_names_has(&own, refs.names[i]))
            v = verdict_of(GRADE_INSPECT_CALL, refs.objects[i], refs.names[i], 0);
    reference_free(&refs);
    grade_names_free(&own);
    return v;
}

#else  /* no libelf: the inspection is the autograder's (Linux) */

bool grade_inspect_course_load(const char *program, const char *const *own_objects, grade_inspect_course *c,
                               char *why, size_t size)
{
    (void)program, (void)own_objects;
    *c = (grade_inspect_course){0};
    grade_msg(why, size, "this grader was built without libelf, which reads ELF objects (install libelf-dev: "
              "tools/setup, then rebuild); on macOS the inspection is the autograder's alone");
    return false;
}

void grade_inspect_course_free(grade_inspect_course *c) { (void)c; }

grade_inspect_verdict grade_inspect_objects(const char *const objects[], int n, const grade_inspect_course *c)
{
    (void)objects, (void)n, (void)c;
    return (grade_inspect_verdict){.code = GRADE_INSPECT_UNREADABLE};
}
#endif

bool grade_inspect_course_add_names(grade_inspect_course *c, const char *path)
{
    char *text = NULL;
    size_t len = 0;
    pl_diag diag = pl_diag_default();
    if (file_read_all(path, "name list", GRADE_TOOL_LOG_MAX, &text, &len, &diag) != PL_OK) return false;
    bool ok = true;
    for (char *save = NULL, *line = strtok_r(text, "\n", &save); ok && line; line = strtok_r(NULL, "\n", &save))
        ok = grade_names_add(&c->program, line);
    free(text);
    return ok;
}

/* ---- what of a verdict may be shown ------------------------------------------------------------ */

void grade_inspect_keep_known(grade_inspect_verdict *v, const grade_inspect_course *c)
{
    v->name[sizeof v->name - 1] = '\0';
    v->known = GRADE_NAME_UNKNOWN;
    if (v->code == GRADE_INSPECT_CALL || v->code == GRADE_INSPECT_REDEFINES)
        v->known = grade_names_has(&c->library, v->name) ? GRADE_NAME_LIBRARY
                 : grade_names_has(&c->program, v->name) ? GRADE_NAME_FRAMEWORK : GRADE_NAME_UNKNOWN;
    else if (v->code == GRADE_INSPECT_BEFORE_MAIN && runtime_section(v->name)) {
        snprintf(v->name, sizeof v->name, "%s", runtime_section(v->name));  /* the list's spelling */
        v->known = GRADE_NAME_RUNTIME;
    }
    else if (v->code == GRADE_INSPECT_BOUND) {
        static const char *const bounds[] = {"sections", "symbols", "a section's name", "a symbol's name", NULL};
        for (const char *const *b = bounds; *b; b++)
            if (!strcmp(v->name, *b)) v->known = GRADE_NAME_BOUND;
    }
    if (v->known == GRADE_NAME_UNKNOWN) v->name[0] = '\0';  /* the student's own: never shown */
}

/* ---- the files the compiler read ---------------------------------------------------------------- */

/* One path the compiler read, relative to the tree (as the dependency file spells it), reduced to
 * a canonical form by folding "x/../" away; false for an absolute path or one leaving the tree. */
static bool tree_path(const char *dep, char *out, size_t size)
{
    if (dep[0] == '/' || strchr(dep, '\\') || strlen(dep) >= size) return false;
    size_t n = 0;
    for (const char *s = dep; *s;) {
        const char *end = strchr(s, '/');
        size_t len = end ? (size_t)(end - s) : strlen(s);
        if (len == 2 && s[0] == '.' && s[1] == '.') {
            if (n == 0) return false;  /* above the tree */
            while (n > 0 && out[n - 1] != '/') n--;
            if (n > 0) n--;            /* the slash before the dropped segment */
        }
        else if (len > 0 && !(len == 1 && s[0] == '.')) {
            if (n > 0) out[n++] = '/';
            memcpy(out + n, s, len);
            n += len;
        }
        s += len + (end != NULL);
    }
    out[n] = '\0';
    return n > 0;
}

static bool is_header(const char *path)
{
    size_t n = strlen(path);
    return n > 2 && !strcmp(path + n - 2, ".h");
}

/* Whether a path the compiler read is the part's own, a framework header or a part's header. */
static bool allowed_input(const char *folder, const char *path)
{
    char own[300];
    const char *slash;
    snprintf(own, sizeof own, "parts/%.200s/", folder);  /* a prefix to compare, not a path to open */
    return !strncmp(path, own, strlen(own)) ||
           (!strncmp(path, "framework/", 10) && !strchr(path + 10, '/') && is_header(path)) ||
           (!strncmp(path, "parts/", 6) && (slash = strchr(path + 6, '/')) && !strncmp(slash + 1, "part", 4) &&
            !strchr(slash + 1, '/') && is_header(path));
}

bool grade_inspect_dependencies(const char *folder, const char *dep_file)
{
    char *text = NULL;
    size_t len = 0;
    pl_diag diag = pl_diag_default();
    if (file_read_all(dep_file, "dependency file", GRADE_TOOL_LOG_MAX, &text, &len, &diag) != PL_OK) return false;
    bool ok = true;
    for (char *save = NULL, *tok = strtok_r(text, " \t\r\n", &save); tok && ok; tok = strtok_r(NULL, " \t\r\n", &save)) {
        size_t n = strlen(tok);
        if (!strcmp(tok, "\\") || tok[n - 1] == ':') continue;  /* a line continuation, or a rule's target */
        char path[1024];
        ok = tree_path(tok, path, sizeof path) && allowed_input(folder, path);
    }
    free(text);
    return ok;
}

/* ---- the grader's stage: the objects read in a confined child ------------------------------------ */

typedef struct {
    const char *objects[GRADE_SOURCE_FILES];
    int count;
    const grade_inspect_course *course;
} inspection;

/* The confined child: the verdict, whole, down the pipe. */
static void inspect_child(void *arg, int out_fd)
{
    const inspection *in = arg;
    grade_inspect_verdict v = grade_inspect_objects(in->objects, in->count, in->course);
    if (write(out_fd, &v, sizeof v) != (ssize_t)sizeof v) _exit(1);
}

/* The verdict a child sent, or false when it sent anything but one well-formed verdict: the child
 * read hostile files, so even its answer is checked before a word of it is used. */
static bool verdict_received(const grade_capture *cap, int count, grade_inspect_verdict *v)
{
    if (cap->overflow || cap->len != (long)sizeof *v) return false;
    memcpy(v, cap->data, sizeof *v);
    v->name[sizeof v->name - 1] = '\0';
    return v->code >= 0 && v->code < GRADE_INSPECT_CODES && v->object >= 0 && v->object < count;
}

/* The course's own objects of the part (its build's, in course_objects), NULL-terminated into list. */
static void course_objects(const char *dir, grade_path_buf *paths, const char **list)
{
    int n = 0;
    DIR *d = opendir(dir);
    for (struct dirent *e; d && n < GRADE_SOURCE_FILES && (e = readdir(d));) {
        size_t len = strlen(e->d_name);
        if (len > 2 && !strcmp(e->d_name + len - 2, ".o") && grade_join(dir, e->d_name, paths[n], GRADE_PATH))
            list[n] = paths[n], n++;
    }
    if (d) closedir(d);
    list[n] = NULL;
}

bool grade_inspect_part(const struct grade_plan *plan, const grade_sandbox *sandbox, struct grade_why *why)
{
    inspection in = {.count = plan->num_sources};
    for (int i = 0; i < in.count; i++) {
        in.objects[i] = plan->sources[i].obj;
        if (!grade_inspect_dependencies(plan->folder, plan->sources[i].dep)) {
            *why = grade_why_of(GRADE_WHY_INCLUDES);
            snprintf(why->file, sizeof why->file, "%s", plan->sources[i].name);
            return false;
        }
    }
    grade_path_buf *own = malloc((GRADE_SOURCE_FILES + 1) * sizeof *own);
    const char *own_list[GRADE_SOURCE_FILES + 1] = {NULL};
    grade_inspect_course c;
    if (own) course_objects(plan->course_objects, own, own_list);
    bool loaded = own && grade_inspect_course_load(plan->course_program, own_list, &c, why->detail, sizeof why->detail);
    free(own);
    if (!loaded) return why->code = GRADE_WHY_COURSE, false;
    in.course = &c;
    /* The objects are hostile: libelf reads them in a child confined like student code, which sends
     * back one fixed-size verdict. */
    grade_capture cap = {.child_fd = 3, .max = sizeof(grade_inspect_verdict)};
    grade_run_opts o = {.wall_seconds = GRADE_INSPECT_SECONDS, .deadline = plan->deadline, .log_path = plan->inspect_log,
                        .log_max = GRADE_LOG_MAX, .untrusted = true, .capture = &cap, .sandbox = sandbox};
    grade_run_result rr = grade_run_function(inspect_child, &in, &o);
    grade_inspect_verdict v;
    bool ok = rr.exited && rr.status == 0 && verdict_received(&cap, in.count, &v);
    if (!ok) {
        *why = grade_why_of(GRADE_WHY_NOT_INSPECTED);
        why->run = rr;
    }
    else if (v.code != GRADE_INSPECT_OK) {
        grade_inspect_keep_known(&v, &c);
        *why = grade_why_of(GRADE_WHY_INSPECTION);
        why->inspect = v;
        snprintf(why->file, sizeof why->file, "%s", plan->sources[v.object].name);
        ok = false;
    }
    free(cap.data);
    grade_inspect_course_free(&c);
    return ok;
}
