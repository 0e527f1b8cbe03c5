/* Counts a process's heap allocations from outside it: an LD_PRELOAD library.
 *
 * Every call of malloc, calloc, realloc, aligned_alloc, posix_memalign, memalign and valloc is
 * counted (libstdc++'s operator new calls malloc, so new is counted too) and passed on to the
 * next definition (dlsym(RTLD_NEXT)). At exit, if MALLOC_COUNT_OUT names a file, one line
 * "count N" is appended to it; unset, nothing is written.
 *
 * MALLOC_COUNT_TRACE_AFTER=N (optional): every allocation after the first N prints a backtrace
 * (backtrace_symbols_fd) to stderr, at most MALLOC_COUNT_TRACE_MAX of them (default 20), each
 * headed "malloc_count: allocation K (FUNCTION, SIZE bytes)" and ended "malloc_count: end". To find
 * a loop's allocations: trace every one (N = 0, MAX large) of a short and a long run and compare
 * how often each stack occurs (addr2line -f -C -e EXE +OFFSET names steplab's own frames); the
 * stacks that occur more often in the long run are the loop's.
 *
 * Build: cc -O2 -shared -fPIC -o libmalloc_count.so tools/malloc_count.c -ldl
 * Use:   MALLOC_COUNT_OUT=/tmp/count LD_PRELOAD=./libmalloc_count.so build/steplab run ...
 *
 * dlsym may itself call calloc (glibc's dlerror buffer) before the real one is known: those
 * calls are served from a small static buffer, whose blocks free and realloc recognise. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <execinfo.h>
#include <fcntl.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static void* (*real_malloc)(size_t);
static void* (*real_calloc)(size_t, size_t);
static void* (*real_realloc)(void*, size_t);
static void (*real_free)(void*);
static void* (*real_aligned_alloc)(size_t, size_t);
static int (*real_posix_memalign)(void**, size_t, size_t);
static void* (*real_memalign)(size_t, size_t);
static void* (*real_valloc)(size_t);

static unsigned long count;      /* allocations so far (updated atomically) */
static int resolving;            /* inside init(): dlsym's own allocations come from boot_buf */
static __thread int tracing __attribute__((tls_model("initial-exec")));  /* inside a backtrace */
static long trace_after = -1;    /* MALLOC_COUNT_TRACE_AFTER, -1: no traces */
static long trace_max = 20;      /* MALLOC_COUNT_TRACE_MAX */
static long traced;

/* The bootstrap buffer: bump allocation, 16-byte aligned, never freed. */
static _Alignas(16) unsigned char boot_buf[8192];
static size_t boot_used;

static int in_boot(const void* p) {
  return (const unsigned char*)p >= boot_buf && (const unsigned char*)p < boot_buf + sizeof boot_buf;
}

static void* boot_alloc(size_t n) {
  const size_t need = (n + 15) & ~(size_t)15;
  if (need > sizeof boot_buf - boot_used) return NULL;
  void* p = boot_buf + boot_used;
  boot_used += need;
  return p; /* static storage: already zero, as calloc must give */
}

/* The bytes of a bootstrap block at p that realloc copies: n, or what is left of boot_buf. */
static size_t boot_copy_len(const void* p, size_t n) {
  const size_t left = (size_t)(boot_buf + sizeof boot_buf - (const unsigned char*)p);
  return n < left ? n : left;
}

static void write_str(const char* s) {
  ssize_t r = write(2, s, strlen(s));
  (void)r;
}

static void init(void) {
  if (real_malloc || resolving) return;
  resolving = 1;
  real_calloc = (void* (*)(size_t, size_t))dlsym(RTLD_NEXT, "calloc");
  real_realloc = (void* (*)(void*, size_t))dlsym(RTLD_NEXT, "realloc");
  real_free = (void (*)(void*))dlsym(RTLD_NEXT, "free");
  real_aligned_alloc = (void* (*)(size_t, size_t))dlsym(RTLD_NEXT, "aligned_alloc");
  real_posix_memalign = (int (*)(void**, size_t, size_t))dlsym(RTLD_NEXT, "posix_memalign");
  real_memalign = (void* (*)(size_t, size_t))dlsym(RTLD_NEXT, "memalign");
  real_valloc = (void* (*)(size_t))dlsym(RTLD_NEXT, "valloc");
  void* (*m)(size_t) = (void* (*)(size_t))dlsym(RTLD_NEXT, "malloc");
  const char* after = getenv("MALLOC_COUNT_TRACE_AFTER");
  if (after && *after) trace_after = strtol(after, NULL, 10);
  const char* max = getenv("MALLOC_COUNT_TRACE_MAX");
  if (max && *max) trace_max = strtol(max, NULL, 10);
  if (!m) {
    write_str("malloc_count: dlsym(RTLD_NEXT, \"malloc\") failed\n");
    _exit(127);
  }
  real_malloc = m; /* last: the other entry points test it */
  resolving = 0;
}

/* Counts one allocation; prints its backtrace if asked. */
static void note(const char* fn, size_t size) {
  const unsigned long k = __atomic_add_fetch(&count, 1, __ATOMIC_RELAXED);
  if (trace_after < 0 || (long)k <= trace_after || tracing) return;
  if (__atomic_add_fetch(&traced, 1, __ATOMIC_RELAXED) > trace_max) return;
  tracing = 1;
  char head[160];
  snprintf(head, sizeof head, "malloc_count: allocation %lu (%s, %zu bytes)\n", k, fn, size);
  write_str(head);
  void* frames[64];
  const int n = backtrace(frames, 64); /* its first call may allocate (loads libgcc_s): not traced */
  backtrace_symbols_fd(frames, n, 2);
  write_str("malloc_count: end\n");
  tracing = 0;
}

void* malloc(size_t n) {
  if (!real_malloc) {
    if (resolving) return boot_alloc(n);
    init();
  }
  note("malloc", n);
  return real_malloc(n);
}

void* calloc(size_t k, size_t n) {
  if (!real_malloc) {
    if (resolving) {
      if (n && k > SIZE_MAX / n) return NULL;
      return boot_alloc(k * n);
    }
    init();
  }
  note("calloc", k * n);
  return real_calloc(k, n);
}

void* realloc(void* p, size_t n) {
  if (!real_malloc) {
    if (resolving) {
      void* q = boot_alloc(n);
      if (q && p) memmove(q, p, boot_copy_len(p, n));
      return q;
    }
    init();
  }
  if (in_boot(p)) { /* a bootstrap block moved to the real heap */
    note("realloc", n);
    void* q = real_malloc(n);
    if (q) memcpy(q, p, boot_copy_len(p, n));
    return q;
  }
  note("realloc", n);
  return real_realloc(p, n);
}

void free(void* p) {
  if (!p || in_boot(p)) return;
  if (!real_free) init();
  real_free(p);
}

void* aligned_alloc(size_t a, size_t n) {
  if (!real_malloc) init();
  note("aligned_alloc", n);
  return real_aligned_alloc(a, n);
}

int posix_memalign(void** out, size_t a, size_t n) {
  if (!real_malloc) init();
  note("posix_memalign", n);
  return real_posix_memalign(out, a, n);
}

void* memalign(size_t a, size_t n) {
  if (!real_malloc) init();
  note("memalign", n);
  return real_memalign(a, n);
}

void* valloc(size_t n) {
  if (!real_malloc) init();
  note("valloc", n);
  return real_valloc(n);
}

/* At exit: "count N" appended to $MALLOC_COUNT_OUT (open/write, no stdio, no allocation). */
__attribute__((destructor)) static void report(void) {
  const char* path = getenv("MALLOC_COUNT_OUT");
  if (!path || !*path) return;
  const int fd = open(path, O_WRONLY | O_CREAT | O_APPEND, 0644);
  if (fd < 0) return;
  char line[64];
  const int len = snprintf(line, sizeof line, "count %lu\n", __atomic_load_n(&count, __ATOMIC_RELAXED));
  if (len > 0) {
    ssize_t r = write(fd, line, (size_t)len);
    (void)r;
  }
  close(fd);
}
