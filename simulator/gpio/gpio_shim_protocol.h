/* simulator/gpio/gpio_shim_protocol.h: how printsim's GPIO emulation and its preload shim hand a
 * line-handle file descriptor to the client (C and C++).
 *
 * The kernel answers GPIO_GET_LINEHANDLE_IOCTL with a new anonymous fd; umockdev's socket
 * protocol cannot create an fd in the client. So the emulated chip answers with a marker
 * (TP_GPIO_HANDLE_MARKER + handle id) in gpiohandle_request.fd; the shim preloaded into the client
 * sees it, opens the chip node again (a new umockdev connection), binds that connection to the
 * handle with TP_GPIO_BIND_HANDLE_IOCTL and gives the client the new fd. Line value ioctls on it
 * reach the emulated chip tagged with their handle; closing it releases the lines. */
#ifndef TP_SIMULATOR_GPIO_SHIM_PROTOCOL_H
#define TP_SIMULATOR_GPIO_SHIM_PROTOCOL_H

#include <linux/ioctl.h>
#include <linux/types.h>

#define TP_GPIO_HANDLE_MARKER 0x54500000
#define TP_GPIO_HANDLE_MAX 0x10000
/* Private request in the GPIO ioctl space (0xB4) at a number the kernel does not use. */
#define TP_GPIO_BIND_HANDLE_IOCTL _IOW(0xB4, 0xF0, __u32)
/* Sent by the shim just before the client closes a handle fd, so the lines are free when close()
 * returns, as with the kernel (umockdev reports the closed connection only later). */
#define TP_GPIO_RELEASE_HANDLE_IOCTL _IO(0xB4, 0xF1)
/* Environment variable naming the emulated chip node the shim reopens. */
#define TP_GPIO_CHIP_ENV "TP_PRINTSIM_GPIOCHIP"

#endif
