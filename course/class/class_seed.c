/* Instructor tooling: not part of any assignment.
 * Seeds: each student's grading seed is HMAC-SHA256(course secret, "pathlab-class-seed/1" NUL id),
 * its first 8 bytes below 10^12 (bin/grade's seeds; the references' are above). So a re-grade
 * draws the same seed and reproduces the score, and no one without the secret can tell a seed
 * from an id: a student cannot prepare for the render their submission will get.
 *
 * The secret is a file of 32 random bytes in hex, made here when missing, readable by its owner
 * only (this program refuses it otherwise) and never printed or written anywhere else. The HMAC is
 * OpenSSL's (libcrypto), computed in this process: the openssl command would take the key on its
 * command line, which every user of the machine can read in /proc. */
#include "class.h"
#include <errno.h>
#include <fcntl.h>
#include <openssl/crypto.h>
#include <openssl/evp.h>
#include <openssl/hmac.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define SEED_LABEL "pathlab-class-seed/1"  /* a new label gives every student new seeds */
#define SECRET_MIN 32                       /* characters of a secret: 128 bits in hex */
#define SECRET_MAX 4096

/* Makes a new secret at path (its folder too, private): false with a line on stderr. */
static bool secret_create(const char *path)
{
    char dir[1024];
    snprintf(dir, sizeof dir, "%s", path);
    char *slash = strrchr(dir, '/');
    if (slash && slash != dir) {
        *slash = '\0';
        if (mkdir(dir, 0700) != 0 && errno != EEXIST) return fprintf(stderr, "grade-class: cannot create %s\n", dir), false;
    }
    /* 32 bytes of the kernel's randomness, as hex: a file an instructor can back up and diff. */
    unsigned char bytes[32];
    char hex[2 * sizeof bytes + 2];
    FILE *random = fopen("/dev/urandom", "rb");
    bool ok = random && fread(bytes, 1, sizeof bytes, random) == sizeof bytes;
    if (random) fclose(random);
    for (size_t i = 0; ok && i < sizeof bytes; i++) snprintf(hex + 2 * i, 3, "%02x", bytes[i]);
    strcat(hex, "\n");
    int fd = ok ? open(path, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600) : -1;
    ok = fd >= 0 && write(fd, hex, strlen(hex)) == (ssize_t)strlen(hex);
    if (fd >= 0 && close(fd) != 0) ok = false;
    OPENSSL_cleanse(bytes, sizeof bytes), OPENSSL_cleanse(hex, sizeof hex);
    if (!ok) return fprintf(stderr, "grade-class: cannot create the course secret %s\n", path), false;
    fprintf(stderr, "grade-class: made a new course secret in %s (readable by you alone): keep it, a re-grade needs it "
                    "to draw the same seeds\n", path);
    return true;
}

/* Reads the secret into key (len bytes): a regular file of this user's, closed to everyone else. */
static bool secret_read(const char *path, char key[SECRET_MAX + 1], size_t *len)
{
    /* Opened without following a link, then checked on the open file (no race with a swap). */
    int fd = open(path, O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0 && errno == ENOENT && secret_create(path)) fd = open(path, O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    struct stat st;
    if (fd < 0 || fstat(fd, &st) != 0) return fprintf(stderr, "grade-class: %s: cannot read the course secret\n", path), false;
    const char *bad = !S_ISREG(st.st_mode) ? "not a regular file"
                      : st.st_uid != geteuid() ? "owned by another user"
                      : (st.st_mode & 077) ? "readable or writable by others (chmod 600 it)" : NULL;
    ssize_t got = bad ? 0 : read(fd, key, SECRET_MAX);
    close(fd);
    *len = got > 0 ? (size_t)got : 0;
    while (*len && strchr(" \t\r\n", key[*len - 1])) (*len)--;
    key[*len] = '\0';
    if (!bad && *len < SECRET_MIN) bad = "shorter than 32 characters";
    if (bad) fprintf(stderr, "grade-class: the course secret %s is %s\n", path, bad);
    return !bad;
}

bool class_seed_all(class_run *r)
{
    char key[SECRET_MAX + 1];
    size_t len;
    if (!secret_read(r->o->secret, key, &len)) return false;
    bool ok = true;
    for (int i = 0; ok && i < r->num_students; i++) {
        class_student *s = &r->students[i];
        unsigned char message[sizeof SEED_LABEL + CLASS_ID_MAX], mac[EVP_MAX_MD_SIZE];
        unsigned int mac_len = 0;
        size_t id_len = strlen(s->id);
        memcpy(message, SEED_LABEL, sizeof SEED_LABEL);  /* with its NUL: the label ends there */
        memcpy(message + sizeof SEED_LABEL, s->id, id_len);
        ok = HMAC(EVP_sha256(), key, (int)len, message, sizeof SEED_LABEL + id_len, mac, &mac_len) && mac_len >= 8;
        uint64_t v = 0;
        for (int b = 0; ok && b < 8; b++) v = v << 8 | mac[b];
        s->seed = v % 1000000000000ull;
        OPENSSL_cleanse(mac, sizeof mac);
    }
    OPENSSL_cleanse(key, sizeof key);
    if (!ok) fprintf(stderr, "grade-class: HMAC-SHA256 failed (libcrypto)\n");
    return ok;
}
