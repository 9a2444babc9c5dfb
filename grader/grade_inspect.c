/* Grader machinery: not part of any assignment.
 * The link-time allow-list: before any of a submission's code runs, the
 * objects the build made from its part, the very files linked into bin/pathtracer and the test
 * suite (graded trees build without link-time optimisation, so they hold machine code), are read:
 * - every undefined symbol must be a part's own function or another part's, or on the allow-list
 *   (grade_allow.c: a narrow framework API, libm, memory, sorting and printing from libc);
 * - no constructors or destructors (.init_array, .fini_array, .ctors, .dtors, .preinit_array): code
 *   that runs before main could act before the grader's checks;
 * - no system call instruction in the machine code (inline assembly around the list);
 * - no global function or variable that a library of the program already defines (a part that
 *   defined cmocka's _assert_int_equal, or malloc, would replace it for the whole program);
 * - every file the compiler read for it (the build's dependency file) is the part's own, a
 *   framework header or a part header: `#include "/autograder/source/parts/part3_direct/direct.c"`
 *   would compile the course's solution as the student's.
 * The first violation is reported naming the file and the symbol; the part then scores zero. */
#include "grade_inspect.h"
#include "grade.h"
#include "grade_tree.h"
#include "../framework/file.h"
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define OBJ_DIR GRADE_OBJECTS
#define LOG_MAX GRADE_TOOL_LOG_MAX

static bool run_to(char *const argv[], const char *cwd, const char *log, bool untrusted)
{
    /* Trusted tools read the submission's objects too: bounded, when not contained. */
    grade_run_opts o = {.wall_seconds = GRADE_INSPECT_SECONDS, .cwd = cwd, .log_path = log, .log_max = LOG_MAX,
                        .untrusted = untrusted, .compiler = true, .bounded = true};
    grade_run_result r = grade_run(argv, &o);
    return r.exited && r.status == 0;
}

/* The output of a shell command run on trusted tools, as text framed by newlines ("\nname\n..."),
 * so defined_in can look a whole line up; NULL when it failed. */
static char *command_lines(const char *cmd, const char *log)
{
    char *argv[] = {"sh", "-c", (char *)cmd, NULL};
    if (!run_to(argv, NULL, log, false)) return NULL;
    char *data = NULL, *text = NULL;
    size_t len = 0;
    pl_diag diag = pl_diag_default();
    if (file_read_all(log, "symbol list", LOG_MAX, &data, &len, &diag) == PL_OK && (text = malloc(len + 3))) {
        text[0] = '\n';
        memcpy(text + 1, data, len);
        text[len + 1] = '\n';
        text[len + 2] = '\0';
    }
    free(data);
    return text;
}

/* The functions the parts define, the submission's own files included: a part may call its own
 * functions, whatever their names, and the other parts' (the framework's are on the allow-list). */
static char *defined_symbols(const char *tree, const char *log)
{
    char cmd[8192];
    snprintf(cmd, sizeof cmd,
             "cd '%s' && for o in " OBJ_DIR "/parts/*/*.o; do "
             "gcc-nm --defined-only --format=just-symbols \"$o\"; done", tree);
    return command_lines(cmd, log);
}

/* Every name the shared libraries of the part's test program define (libc, libm, cmocka, ...) and
 * the libraries they load in turn (libxml2's liblzma and libz, libgcc_s), found from the NEEDED
 * entries, breadth first, through the compiler's own library search path. Transitive ones count:
 * a part that defines lzma_code would otherwise run its code inside the scene loader, unseen. */
static char *library_symbols(const char *program, const char *log)
{
    char cmd[8192];
    snprintf(cmd, sizeof cmd,
             "needed() { readelf -d \"$1\" 2>/dev/null | sed -n 's/.*Shared library: \\[\\(.*\\)\\]/\\1/p'; }; "
             "todo=$(needed '%s'); seen=' '; "
             "while [ -n \"$todo\" ]; do set -- $todo; l=$1; shift; todo=\"$*\"; "
             "case \"$seen\" in *\" $l \"*) continue;; esac; seen=\"$seen$l \"; "
             "p=$(gcc -print-file-name=$l); [ -f \"$p\" ] || continue; "
             "nm -D --defined-only --format=just-symbols --without-symbol-versions \"$p\"; "
             "todo=\"$todo $(needed \"$p\")\"; done", program);
    return command_lines(cmd, log);
}

static bool defined_in(const char *symbols, const char *name)
{
    char needle[300];
    snprintf(needle, sizeof needle, "\n%s\n", name);
    return strstr(symbols, needle) != NULL;
}

/* Scans one tool's output (in log) line by line for a violation; fills why on the first. */
typedef bool (*line_check)(const char *line, const char *symbols, char *why, size_t size);

static bool scan(const char *log, line_check check, const char *symbols, char *why, size_t size)
{
    FILE *f = fopen(log, "r");
    if (!f) return false;
    char line[1024];
    bool bad = false;
    while (!bad && fgets(line, sizeof line, f)) {
        line[strcspn(line, "\r\n")] = '\0';
        bad = check(line, symbols, why, size);
    }
    fclose(f);
    return bad;
}

static bool bad_symbol(const char *line, const char *symbols, char *why, size_t size)
{
    const char *name = line;
    while (*name == ' ') name++;
    if (!*name || defined_in(symbols, name) || grade_allowed_symbol(name)) return false;
    grade_msg(why, size, "calls `%s`, which part code may not use (handout/README.md, \"What your part may "
                        "call\", lists what it may)", name);
    return true;
}

static bool bad_section(const char *line, const char *symbols, char *why, size_t size)
{
    (void)symbols;
    /* Link-time optimisation's bytecode would have the linker run the compiler on it, as the
     * grader: an object must hold machine code only (the graded build compiles without -flto). */
    if (strstr(line, ".gnu.lto_")) {
        grade_msg(why, size, "holds link-time optimisation bytecode (a .gnu.lto_ section), not machine code");
        return true;
    }
    static const char *const sections[] = {".init_array", ".fini_array", ".preinit_array", ".ctors", ".dtors", NULL};
    for (const char *const *s = sections; *s; s++)
        if (strstr(line, *s)) {
            grade_msg(why, size, "has a constructor or destructor (section %s): code may not run outside its tasks", *s);
            return true;
        }
    return false;
}

static bool bad_instruction(const char *line, const char *symbols, char *why, size_t size)
{
    (void)symbols;
    /* objdump -d prints "syscall", "sysenter" or "int $0x80" as the mnemonic column. */
    if (strstr(line, "\tsyscall") || strstr(line, "\tsysenter") || strstr(line, "\tint    $0x80")) {
        grade_msg(why, size, "contains a system call instruction: part code may not talk to the kernel");
        return true;
    }
    return false;
}

static bool bad_definition(const char *line, const char *library, char *why, size_t size)
{
    const char *name = line;
    while (*name == ' ') name++;
    if (!*name || !defined_in(library, name)) return false;
    grade_msg(why, size, "defines `%s`, which a library of the program already defines: part code may not "
                        "replace library functions (rename it, or make it static)", name);
    return true;
}

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

/* The files the compiler read for obj's source, from the build's dependency file (-MMD lists every
 * header outside the system's folders): each must be the part's own (parts/<folder>/), a framework
 * header or a part's header. */
static bool is_header(const char *path)
{
    size_t n = strlen(path);
    return n > 2 && !strcmp(path + n - 2, ".h");
}

static bool bad_dependencies(const char *folder, const char *dep_file, char *why, size_t size)
{
    char *text = NULL;
    size_t len = 0;
    pl_diag diag = pl_diag_default();
    if (file_read_all(dep_file, "dependency file", LOG_MAX, &text, &len, &diag) != PL_OK)
        return grade_msg(why, size, "the build left no dependency file (%s)", diag.error), true;
    bool bad = false;
    char own[300];
    grade_path(own, sizeof own, "parts/%s/", folder);
    for (char *save = NULL, *tok = strtok_r(text, " \t\r\n", &save); tok && !bad; tok = strtok_r(NULL, " \t\r\n", &save)) {
        size_t n = strlen(tok);
        if (!strcmp(tok, "\\") || tok[n - 1] == ':') continue;  /* a line continuation, or a rule's target */
        char path[1024];
        const char *slash;
        bool ok = tree_path(tok, path, sizeof path) &&
                  (!strncmp(path, own, strlen(own)) ||
                   (!strncmp(path, "framework/", 10) && !strchr(path + 10, '/') && is_header(path)) ||
                   (!strncmp(path, "parts/", 6) && (slash = strchr(path + 6, '/')) && !strncmp(slash + 1, "part", 4) &&
                    !strchr(slash + 1, '/') && is_header(path)));
        if (!ok) {
            grade_msg(why, size, "reads `%.300s` when compiled: part code may include only its own files and the "
                                "framework's and parts' headers", tok);
            bad = true;
        }
    }
    free(text);
    return bad;
}

bool grade_inspect_part(const char *tree, const char *folder, const char *program, const char *work, bool untrusted,
                        char *why, size_t size)
{
    char log[4200], src_dir[4200];
    grade_path(src_dir, sizeof src_dir, "%s/parts/%s", tree, folder);
    grade_path(log, sizeof log, "%s/inspect-symbols.txt", work);
    char *symbols = defined_symbols(tree, log);
    grade_path(log, sizeof log, "%s/inspect-libraries.txt", work);
    char *library = library_symbols(program, log);
    if (!symbols || !library) {
        free(symbols);
        free(library);
        return grade_msg(why, size, "cannot list the parts' and the libraries' symbols"), false;
    }

    /* Each .c of the part has its object, made by the build with the build's own flags. */
    bool ok = true;
    DIR *d = opendir(src_dir);
    if (!d) {
        grade_msg(why, size, "cannot read parts/%s", folder);
        ok = false;
    }
    for (struct dirent *e; ok && d && (e = readdir(d));) {
        size_t n = strlen(e->d_name);
        if (n < 3 || strcmp(e->d_name + n - 2, ".c")) continue;
        char obj[4400], tool_log[4400], what[512] = "";
        struct stat st;
        grade_path(obj, sizeof obj, "%s/" OBJ_DIR "/parts/%s/%.*s.o", tree, folder, (int)n - 2, e->d_name);
        grade_path(tool_log, sizeof tool_log, "%s/inspect-%s.log", work, e->d_name);
        if (stat(obj, &st) != 0 || !S_ISREG(st.st_mode)) {
            grade_msg(why, size, "parts/%s/%s: the build made no object file from it", folder, e->d_name);
            ok = false;
            break;
        }
        /* The tools read hostile files: they run contained, like the code. */
        char *nm[] = {"nm", "-u", "--format=just-symbols", obj, NULL};
        char *nm_defined[] = {"nm", "--defined-only", "--extern-only", "--format=just-symbols", obj, NULL};
        char *readelf[] = {"readelf", "-S", "-W", obj, NULL};
        char *objdump[] = {"objdump", "-d", obj, NULL};
        struct { char **argv; line_check check; const char *names; } steps[] = {
            {nm, bad_symbol, symbols}, {nm_defined, bad_definition, library}, {readelf, bad_section, NULL},
            {objdump, bad_instruction, NULL}};
        char dep[4400];
        grade_path(dep, sizeof dep, "%s/" OBJ_DIR "/parts/%s/%.*s.d", tree, folder, (int)n - 2, e->d_name);
        if (bad_dependencies(folder, dep, what, sizeof what)) {
            grade_msg(why, size, "parts/%s/%s: %s", folder, e->d_name, what);
            ok = false;
        }
        for (size_t k = 0; ok && k < sizeof steps / sizeof steps[0]; k++) {
            if (!run_to(steps[k].argv, NULL, tool_log, untrusted) ||
                scan(tool_log, steps[k].check, steps[k].names, what, sizeof what)) {
                grade_msg(why, size, "parts/%s/%s: %s", folder, e->d_name, what[0] ? what : "could not be inspected "
                         "(not an object file: was it built with link-time optimisation?)");
                ok = false;
            }
        }
    }
    if (d) closedir(d);
    free(symbols);
    free(library);
    return ok;
}
