/* simulator/app/preload/tp_gpio_preload.c: preloaded into programs run by printsim, ahead of
 * umockdev's preload. It fills two gaps in umockdev for GPIO: it turns the emulated chip's
 * line-handle marker into a real fd (see simulator/gpio/gpio_shim_protocol.h), and it points
 * scandir("/dev") at the testbed, which umockdev does not redirect, so that libgpiod's chip
 * iteration (`gpiodetect`, `gpioinfo` without arguments) finds the emulated chip. Closing a
 * handle fd releases its lines before close() returns, as the kernel does. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <linux/gpio.h>
#include <dirent.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "simulator/gpio/gpio_shim_protocol.h"

typedef int (*ioctl_fn)(int, unsigned long, ...);
typedef int (*close_fn)(int);

/* The line-handle fds this process holds, so close() can release their lines first. */
#define MAX_HANDLE_FDS 256
static int handle_fds[MAX_HANDLE_FDS];
static int handle_count = 0;

static ioctl_fn next_ioctl(void) {
  static ioctl_fn next = NULL;
  if (!next) next = (ioctl_fn)dlsym(RTLD_NEXT, "ioctl");
  return next;
}

int ioctl(int fd, unsigned long request, ...) {
  ioctl_fn next = next_ioctl();
  va_list ap;
  va_start(ap, request);
  void* arg = va_arg(ap, void*);
  va_end(ap);

  int r = next(fd, request, arg);
  if (r != 0 || request != GPIO_GET_LINEHANDLE_IOCTL || arg == NULL) return r;
  struct gpiohandle_request* req = (struct gpiohandle_request*)arg;
  if (req->fd < TP_GPIO_HANDLE_MARKER || req->fd >= TP_GPIO_HANDLE_MARKER + TP_GPIO_HANDLE_MAX) return r;

  /* A marker from printsim: open a connection for the handle and bind it. */
  const char* chip = getenv(TP_GPIO_CHIP_ENV);
  if (chip == NULL) {
    errno = ENOTSUP;
    return -1;
  }
  __u32 id = (__u32)(req->fd - TP_GPIO_HANDLE_MARKER);
  int hfd = open(chip, O_RDWR | O_CLOEXEC);
  if (hfd < 0) return -1;
  if (next(hfd, TP_GPIO_BIND_HANDLE_IOCTL, &id) != 0) {
    int saved = errno;
    close(hfd);
    errno = saved;
    return -1;
  }
  req->fd = hfd;
  if (handle_count < MAX_HANDLE_FDS) handle_fds[handle_count++] = hfd;
  return 0;
}

int close(int fd) {
  static close_fn next = NULL;
  if (!next) next = (close_fn)dlsym(RTLD_NEXT, "close");
  for (int i = 0; i < handle_count; ++i) {
    if (handle_fds[i] != fd) continue;
    handle_fds[i] = handle_fds[--handle_count];
    int saved = errno;
    next_ioctl()(fd, TP_GPIO_RELEASE_HANDLE_IOCTL, 0);
    errno = saved;
    break;
  }
  return next(fd);
}

/* scandir of /dev lists the testbed's /dev (the emulated nodes) when umockdev is active. */
typedef int (*filter_fn)(const struct dirent*);
typedef int (*compar_fn)(const struct dirent**, const struct dirent**);
typedef int (*scandir_fn)(const char*, struct dirent***, filter_fn, compar_fn);

static const char* testbed_dir(const char* dir, char* buf, size_t size) {
  const char* root = getenv("UMOCKDEV_DIR");
  if (root == NULL || dir == NULL || strcmp(dir, "/dev") != 0) return dir;
  snprintf(buf, size, "%s/dev", root);
  return buf;
}

int scandir(const char* dir, struct dirent*** namelist, filter_fn filter, compar_fn compar) {
  static scandir_fn next = NULL;
  if (!next) next = (scandir_fn)dlsym(RTLD_NEXT, "scandir");
  char buf[4096];
  return next(testbed_dir(dir, buf, sizeof buf), namelist, filter, compar);
}

typedef int (*filter64_fn)(const struct dirent64*);
typedef int (*compar64_fn)(const struct dirent64**, const struct dirent64**);
typedef int (*scandir64_fn)(const char*, struct dirent64***, filter64_fn, compar64_fn);

int scandir64(const char* dir, struct dirent64*** namelist, filter64_fn filter, compar64_fn compar) {
  static scandir64_fn next = NULL;
  if (!next) next = (scandir64_fn)dlsym(RTLD_NEXT, "scandir64");
  char buf[4096];
  return next(testbed_dir(dir, buf, sizeof buf), namelist, filter, compar);
}
