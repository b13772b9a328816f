/* @file
 * @brief LD_PRELOAD fault injector for tests: makes chosen system calls fail the way a full disk,
 * a failing device or a kill does, so the real vdfx executable can be tested against them.
 *
 * VDFX_FAULT selects one fault (unset: every call goes through unchanged):
 *   fsync_dir      fsync of a folder fails with EIO (the file itself was already renamed)
 *   fsync_file     fsync of a regular file fails with EIO
 *   rename         rename fails with EIO
 *   rename_kill    the process is killed (SIGKILL) at its first rename: a crash mid-save
 *   write_enospc   writes to regular files fail with ENOSPC after VDFX_FAULT_AFTER bytes (default
 *                  0) have gone through: a disk that fills up
 * Calls are forwarded with dlsym(RTLD_NEXT), so the rest of the process is unaffected.
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
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

int fsync(int fd) {
  static int (*real)(int) = NULL;
  if (real == NULL) next_symbol(&real, sizeof real, "fsync");
  if ((fault_is("fsync_dir") && fd_is(fd, S_IFDIR)) ||
      (fault_is("fsync_file") && fd_is(fd, S_IFREG))) {
    errno = EIO;
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

ssize_t write(int fd, const void* buf, size_t n) {
  static ssize_t (*real)(int, const void*, size_t) = NULL;
  static long long passed = 0;
  if (real == NULL) next_symbol(&real, sizeof real, "write");
  if (fault_is("write_enospc") && fd_is(fd, S_IFREG)) {
    const char* after = getenv("VDFX_FAULT_AFTER");
    const long long limit = after != NULL ? atoll(after) : 0;
    if (passed + (long long)n > limit) {
      errno = ENOSPC;
      return -1;
    }
    passed += (long long)n;
  }
  return real(fd, buf, n);
}
