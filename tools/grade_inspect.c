/* Grader machinery: not part of any assignment.
 * The link-time allow-list (DESIGN.md section 9): before any of a submission's code runs, its part
 * is compiled once more on its own, without link-time optimisation, and the objects inspected:
 * - every undefined symbol must be the framework's or another part's (what the headers offer), a
 *   libm function, or one of a short list from libc (memory, sorting, formatted printing);
 * - no constructors or destructors (.init_array, .fini_array, .ctors, .dtors, .preinit_array): code
 *   that runs before main could act before the grader's checks;
 * - no system call instruction in the machine code (inline assembly around the list).
 * The first violation is reported naming the file and the symbol; the part then scores zero. */
#include "grade_inspect.h"
#include "grade.h"
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define INSPECT_SECONDS 120
#define LOG_MAX (4 << 20)

/* libc and libm functions part code may call. Everything else from libc (files, processes,
 * sockets, exit, environment, time) is refused. Compiler helpers are allowed too. */
static const char *const allowed_libc[] = {
    "memcpy", "memmove", "memset", "memcmp", "strlen", "strcmp", "strncmp", "strchr", "strstr",
    "malloc", "calloc", "realloc", "free", "qsort", "bsearch", "abs", "labs",
    "printf", "fprintf", "puts", "fputs", "putchar", "fputc", "snprintf", "sprintf", "vsnprintf", "fflush",
    "stdout", "stderr", "__assert_fail", "__stack_chk_fail", "_GLOBAL_OFFSET_TABLE_", "__printf_chk",
    "__fprintf_chk", "__sprintf_chk", "__snprintf_chk", "__memcpy_chk", "__memset_chk", "__memmove_chk",
    NULL};
static const char *const allowed_libm[] = {
    "sqrt", "cbrt", "hypot", "exp", "exp2", "expm1", "log", "log2", "log10", "log1p", "pow", "sin", "cos", "tan",
    "asin", "acos", "atan", "atan2", "sinh", "cosh", "tanh", "fabs", "floor", "ceil", "round", "trunc", "fmod",
    "fmin", "fmax", "copysign", "nextafter", "ldexp", "frexp", "erf", "erfc", "lgamma", "tgamma", "sincos", NULL};

static bool in_list(const char *const *list, const char *s)
{
    for (; *list; list++)
        if (!strcmp(*list, s)) return true;
    return false;
}

/* libm names come in double and float (f suffix) forms. */
static bool libm_function(const char *s)
{
    char base[64];
    size_t n = strlen(s);
    if (n == 0 || n >= sizeof base) return false;
    if (in_list(allowed_libm, s)) return true;
    snprintf(base, sizeof base, "%.*s", (int)n - 1, s);
    return s[n - 1] == 'f' && in_list(allowed_libm, base);
}

static bool run_to(char *const argv[], const char *cwd, const char *log, bool untrusted)
{
    grade_run_opts o = {INSPECT_SECONDS, cwd, log, LOG_MAX, NULL, untrusted};
    grade_run_result r = grade_run(argv, &o);
    return r.exited && r.status == 0;
}

/* The symbols the program defines: every framework object's and every part's, the submission's own
 * files included (a part may call its own functions, whatever their names). */
static char *defined_symbols(const char *tree, const char *log)
{
    char cmd[8192];
    snprintf(cmd, sizeof cmd,
             "cd '%s' && for o in build/release/framework/*.o build/release/parts/*/*.o; do "
             "gcc-nm --defined-only --format=just-symbols \"$o\"; done", tree);
    char *argv[] = {"sh", "-c", cmd, NULL};
    if (!run_to(argv, NULL, log, false)) return NULL;
    FILE *f = fopen(log, "r");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    long size = ftell(f);
    rewind(f);
    char *text = malloc((size_t)size + 3);
    if (text) {
        text[0] = '\n';
        size_t got = fread(text + 1, 1, (size_t)size, f);
        text[got + 1] = '\n';
        text[got + 2] = '\0';
    }
    fclose(f);
    return text;
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
    if (!*name || defined_in(symbols, name) || in_list(allowed_libc, name) || libm_function(name)) return false;
    snprintf(why, size, "calls `%s`, which part code may not use (allowed: the framework's and the parts' "
                        "functions, libm, and memory, sorting and printing functions from libc)", name);
    return true;
}

static bool bad_section(const char *line, const char *symbols, char *why, size_t size)
{
    (void)symbols;
    static const char *const sections[] = {".init_array", ".fini_array", ".preinit_array", ".ctors", ".dtors", NULL};
    for (const char *const *s = sections; *s; s++)
        if (strstr(line, *s)) {
            snprintf(why, size, "has a constructor or destructor (section %s): code may not run outside its tasks", *s);
            return true;
        }
    return false;
}

static bool bad_instruction(const char *line, const char *symbols, char *why, size_t size)
{
    (void)symbols;
    /* objdump -d prints "syscall", "sysenter" or "int $0x80" as the mnemonic column. */
    if (strstr(line, "\tsyscall") || strstr(line, "\tsysenter") || strstr(line, "\tint    $0x80")) {
        snprintf(why, size, "contains a system call instruction: part code may not talk to the kernel");
        return true;
    }
    return false;
}

bool grade_inspect_part(const char *tree, const char *folder, const char *work, bool untrusted, char *why,
                        size_t size)
{
    char dir[4096], log[4200], src_dir[4200];
    snprintf(dir, sizeof dir, "%s/inspect", work);
    snprintf(src_dir, sizeof src_dir, "%s/parts/%s", tree, folder);
    char *mk[] = {"mkdir", "-p", dir, NULL};
    snprintf(log, sizeof log, "%s/symbols.txt", dir);
    if (!run_to(mk, NULL, NULL, untrusted)) return snprintf(why, size, "cannot create %s", dir), false;
    char *symbols = defined_symbols(tree, log);
    if (!symbols) return snprintf(why, size, "cannot list the framework's symbols"), false;

    bool ok = true;
    DIR *d = opendir(src_dir);
    for (struct dirent *e; ok && d && (e = readdir(d));) {
        size_t n = strlen(e->d_name);
        if (n < 3 || strcmp(e->d_name + n - 2, ".c")) continue;
        char src[4400], obj[4400], inc[4400], tool_log[4400], what[512] = "";
        snprintf(src, sizeof src, "%s/%s", src_dir, e->d_name);
        snprintf(obj, sizeof obj, "%s/%s.o", dir, e->d_name);
        snprintf(inc, sizeof inc, "-I%s/build/release/gen", tree);
        snprintf(tool_log, sizeof tool_log, "%s/%s.log", dir, e->d_name);
        /* Compiled as the build does, but into plain machine code (no LTO) so it can be read. */
        char *cc[] = {"cc", "-std=c11", "-O2", "-fno-lto", "-D_GNU_SOURCE", "-I/usr/include/libxml2", inc, "-c",
                      src, "-o", obj, NULL};
        if (!run_to(cc, NULL, tool_log, untrusted)) {
            snprintf(why, size, "parts/%s/%s: does not compile on its own (see %s)", folder, e->d_name, tool_log);
            ok = false;
            break;
        }
        char *nm[] = {"nm", "-u", "--format=just-symbols", obj, NULL};
        char *readelf[] = {"readelf", "-S", "-W", obj, NULL};
        char *objdump[] = {"objdump", "-d", obj, NULL};
        struct { char **argv; line_check check; } steps[] = {{nm, bad_symbol}, {readelf, bad_section},
                                                             {objdump, bad_instruction}};
        for (size_t k = 0; ok && k < sizeof steps / sizeof steps[0]; k++) {
            if (!run_to(steps[k].argv, NULL, tool_log, false) || scan(tool_log, steps[k].check, symbols, what, sizeof what)) {
                snprintf(why, size, "parts/%s/%s: %s", folder, e->d_name, what[0] ? what : "could not be inspected");
                ok = false;
            }
        }
    }
    if (d) closedir(d);
    free(symbols);
    return ok;
}
