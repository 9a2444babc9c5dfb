/* OpenEXR through a FILE (exr_io.h): the write callback, the quiet error handler, the messages. */
#include "exr_io.h"
#include <errno.h>
#include <string.h>
#include <unistd.h>

/* OpenEXR's write callback: the stream is the FILE's descriptor, written at explicit offsets. */
static int64_t write_at(exr_const_context_t ctxt, void *user, const void *buf, uint64_t size, uint64_t offset,
                        exr_stream_error_func_ptr_t error_cb)
{
    int fd = *(const int *)user;
    const char *p = buf;
    uint64_t done = 0;
    while (done < size) {
        ssize_t n = pwrite(fd, p + done, size - done, (off_t)(offset + done));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            error_cb(ctxt, EXR_ERR_WRITE_IO, "pwrite: %s", strerror(errno));
            return -1;
        }
        done += (uint64_t)n;
    }
    return (int64_t)done;
}

/* OpenEXR prints its errors by default; pathlab reports them once, with the file's name. */
void exrio_quiet_errors(exr_const_context_t ctxt, exr_result_t code, const char *msg)
{
    (void)ctxt, (void)code, (void)msg;  /* reported through the result codes instead */
}

/* An OpenEXR result code as pathlab's status and message. */
pl_status exrio_fail(pl_diag *diag, const char *what, exr_result_t r)
{
    return pl_fail(diag, PL_ERR_IO, "%s: OpenEXR: %s", what, exr_get_default_error_message(r));
}

/* A write context on file's descriptor, stored in *fd (OpenEXR's write_at reads it there, so it must
 * outlive the context). Whatever file has buffered goes first: OpenEXR writes at offsets from 0. */
exr_result_t exrio_start_write(FILE *file, int *fd, const char *name, exr_context_t *x)
{
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    *fd = fileno(file);
    init.user_data = fd;
    init.write_fn = write_at;
    init.error_handler_fn = exrio_quiet_errors;
    *x = NULL;
    fflush(file);
    return exr_start_write(x, name, EXR_WRITE_FILE_DIRECTLY, &init);
}
