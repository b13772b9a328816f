/* @file
 * @brief LD_PRELOAD fault injector for tests: makes chosen system calls fail the way a full disk,
 * a failing device or a kill does, so the real vdfx executable can be tested against them.
 *
 * VDFX_FAULT selects one fault (unset: every call goes through unchanged):
 *   fsync_dir      fsync of a folder fails with EIO (the file itself was already renamed)
 *   fsync_file     fsync of a regular file fails with EIO
 *   rename         rename fails with EIO
 *   rename_kill    the process is killed (SIGKILL) at its first rename: a crash mid-save
 *   write_enospc   writes to regular files (write, writev, sendfile, copy_file_range) fail with
 *                  ENOSPC after VDFX_FAULT_AFTER bytes (default 0) have gone through: a disk that
 *                  fills up
 * For fsync_dir and fsync_file:
 *   VDFX_FAULT_PATH   only the descriptor of this path fails (its absolute path as the kernel
 *                     names it in /proc/self/fd): one folder that cannot be synced
 *   VDFX_FAULT_ERRNO  EIO (the default), EINVAL (a file system that cannot sync a folder) or EROFS
 * Independent of VDFX_FAULT:
 *   VDFX_OPEN_LOG     a file: every path the process asks to open (open, openat, opendir, fopen)
 *                     is appended to it, made absolute, one per line, before the call, so a test
 *                     can check what vdfx opened (and an open that blocks is logged too)
 * Calls are forwarded with dlsym(RTLD_NEXT), so the rest of the process is unaffected.
 */
#define _GNU_SOURCE
#include <dirent.h>
#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/sendfile.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/types.h>
#include <sys/uio.h>
#include <unistd.h>

/* The next definition of `name` (glibc's). memcpy, not a cast: ISO C has no conversion from an
 * object pointer to a function pointer, and POSIX guarantees the representations agree. */
static void next_symbol(void* function_pointer, size_t size, const char* name) {
  void* p = dlsym(RTLD_NEXT, name);
  memcpy(function_pointer, &p, size);
}

static int fault_is(const char* name) {
  const char* f = getenv("VDFX_FAULT");
  return f != NULL && strcmp(f, name) == 0;
}

static int fd_is(int fd, mode_t type) {
  struct stat st;
  return fstat(fd, &st) == 0 && (st.st_mode & S_IFMT) == type;
}

/* The path the kernel gives descriptor fd ("" when it has none). */
static void fd_path(int fd, char* out, size_t size) {
  char link[64];
  snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
  const ssize_t n = readlink(link, out, size - 1);
  out[n > 0 ? n : 0] = '\0';
}

/* VDFX_FAULT_PATH, when set, restricts a fault to the descriptor of that path. */
static int fd_selected(int fd) {
  const char* only = getenv("VDFX_FAULT_PATH");
  if (only == NULL) return 1;
  char path[PATH_MAX];
  fd_path(fd, path, sizeof path);
  return strcmp(path, only) == 0;
}

static int fault_errno(void) {
  const char* e = getenv("VDFX_FAULT_ERRNO");
  if (e != NULL && strcmp(e, "EINVAL") == 0) return EINVAL;
  if (e != NULL && strcmp(e, "EROFS") == 0) return EROFS;
  return EIO;
}

int fsync(int fd) {
  static int (*real)(int) = NULL;
  if (real == NULL) next_symbol(&real, sizeof real, "fsync");
  if (((fault_is("fsync_dir") && fd_is(fd, S_IFDIR)) ||
       (fault_is("fsync_file") && fd_is(fd, S_IFREG))) &&
      fd_selected(fd)) {
    errno = fault_errno();
    return -1;
  }
  return real(fd);
}

int rename(const char* from, const char* to) {
  static int (*real)(const char*, const char*) = NULL;
  if (real == NULL) next_symbol(&real, sizeof real, "rename");
  if (fault_is("rename_kill")) raise(SIGKILL);
  if (fault_is("rename")) {
    errno = EIO;
    return -1;
  }
  return real(from, to);
}

/* write_enospc: whether `n` more bytes to fd would pass VDFX_FAULT_AFTER (errno set then). */
static int disk_full(int fd, long long n) {
  static long long passed = 0;
  if (!fault_is("write_enospc") || !fd_is(fd, S_IFREG)) return 0;
  const char* after = getenv("VDFX_FAULT_AFTER");
  const long long limit = after != NULL ? atoll(after) : 0;
  if (passed + n > limit) {
    errno = ENOSPC;
    return 1;
  }
  passed += n;
  return 0;
}

ssize_t write(int fd, const void* buf, size_t n) {
  static ssize_t (*real)(int, const void*, size_t) = NULL;
  if (real == NULL) next_symbol(&real, sizeof real, "write");
  if (disk_full(fd, (long long)n)) return -1;
  return real(fd, buf, n);
}

ssize_t writev(int fd, const struct iovec* iov, int count) {
  static ssize_t (*real)(int, const struct iovec*, int) = NULL;
  if (real == NULL) next_symbol(&real, sizeof real, "writev");
  long long n = 0;
  for (int i = 0; i < count; ++i) n += (long long)iov[i].iov_len;
  if (disk_full(fd, n)) return -1;
  return real(fd, iov, count);
}

ssize_t sendfile(int out, int in, off_t* offset, size_t n) {
  static ssize_t (*real)(int, int, off_t*, size_t) = NULL;
  if (real == NULL) next_symbol(&real, sizeof real, "sendfile");
  if (disk_full(out, (long long)n)) return -1;
  return real(out, in, offset, n);
}

ssize_t copy_file_range(int in, off_t* in_off, int out, off_t* out_off, size_t n,
                        unsigned flags) {
  static ssize_t (*real)(int, off_t*, int, off_t*, size_t, unsigned) = NULL;
  if (real == NULL) next_symbol(&real, sizeof real, "copy_file_range");
  if (disk_full(out, (long long)n)) return -1;
  return real(in, in_off, out, out_off, n, flags);
}

/* VDFX_OPEN_LOG: appends `path` (made absolute against dirfd, or the working folder) and a
 * newline to the log with raw system calls (nothing here is interposed again). */
static void log_open(int dirfd, const char* path) {
  const char* log = getenv("VDFX_OPEN_LOG");
  if (log == NULL || path == NULL) return;
  char line[2 * PATH_MAX + 2];
  line[0] = '\0';
  if (path[0] != '/') {
    if (dirfd == AT_FDCWD) {
      if (getcwd(line, PATH_MAX) == NULL) line[0] = '\0';
    } else {
      fd_path(dirfd, line, PATH_MAX);
    }
    strcat(line, "/");
  }
  strncat(line, path, PATH_MAX);
  strcat(line, "\n");
  const int fd = (int)syscall(SYS_openat, AT_FDCWD, log, O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC,
                              0644);
  if (fd < 0) return;
  if (syscall(SYS_write, fd, line, strlen(line)) < 0) { /* best effort: a test log */
  }
  syscall(SYS_close, fd);
}

/* The mode argument of an open that creates (O_CREAT, O_TMPFILE), else 0. */
#define OPEN_MODE(flags, last, mode)                                        \
  do {                                                                      \
    if ((flags) & (O_CREAT | O_TMPFILE)) {                                  \
      va_list ap;                                                           \
      va_start(ap, last);                                                   \
      mode = (mode_t)va_arg(ap, int);                                       \
      va_end(ap);                                                           \
    }                                                                       \
  } while (0)

#define FORWARD_OPEN(name)                                               \
  int name(const char* path, int flags, ...) {                          \
    static int (*real)(const char*, int, ...) = NULL;                   \
    if (real == NULL) next_symbol(&real, sizeof real, #name);           \
    mode_t mode = 0;                                                    \
    OPEN_MODE(flags, flags, mode);                                      \
    log_open(AT_FDCWD, path);                                           \
    return real(path, flags, mode);                                     \
  }
FORWARD_OPEN(open)
FORWARD_OPEN(open64)

#define FORWARD_OPENAT(name)                                             \
  int name(int dirfd, const char* path, int flags, ...) {               \
    static int (*real)(int, const char*, int, ...) = NULL;              \
    if (real == NULL) next_symbol(&real, sizeof real, #name);           \
    mode_t mode = 0;                                                    \
    OPEN_MODE(flags, flags, mode);                                      \
    log_open(dirfd, path);                                              \
    return real(dirfd, path, flags, mode);                              \
  }
FORWARD_OPENAT(openat)
FORWARD_OPENAT(openat64)

DIR* opendir(const char* path) {
  static DIR* (*real)(const char*) = NULL;
  if (real == NULL) next_symbol(&real, sizeof real, "opendir");
  log_open(AT_FDCWD, path);
  return real(path);
}

#define FORWARD_FOPEN(name)                                              \
  FILE* name(const char* path, const char* how) {                       \
    static FILE* (*real)(const char*, const char*) = NULL;              \
    if (real == NULL) next_symbol(&real, sizeof real, #name);           \
    log_open(AT_FDCWD, path);                                           \
    return real(path, how);                                             \
  }
FORWARD_FOPEN(fopen)
FORWARD_FOPEN(fopen64)
