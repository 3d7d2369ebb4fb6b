/* analyse-client.c - "$ANALYSE" SUBCOMMAND ARGS... through the analysis server
 * (tools/analysis_server.py): hands the server its standard input, output and error
 * (SCM_RIGHTS), its working directory and its arguments, and exits with the status of the call,
 * which a fork of the server runs on those descriptors. Built static (build/analyse-client, the
 * Makefile), so that starting it maps no shared library: the point is a call that costs a few
 * milliseconds instead of a python start.
 *
 * env: DPD_ANALYSE_SOCKET  the server's socket (tools/lib/exp.sh, analyse_serve)
 *      DPD_ANALYSE_FALLBACK tools/analyse, run instead (with DPD_ANALYSE_SOCKET removed) whenever
 *                           the call cannot be handed over: no socket, no server, a descriptor
 *                           0-2 closed. Once handed over, a call is never run twice: a server
 *                           that ends without answering is an error (status 70). */
#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

/* the call cannot be handed over: tools/analyse runs it */
static int fallback(char **argv)
{
    const char *script = getenv("DPD_ANALYSE_FALLBACK");
    if (!script || !*script) {
        fprintf(stderr, "analyse-client: no analysis server and no DPD_ANALYSE_FALLBACK (tools/analyse)\n");
        return 127;
    }
    unsetenv("DPD_ANALYSE_SOCKET");
    argv[0] = (char *)script;
    execv(script, argv);
    fprintf(stderr, "analyse-client: cannot run %s: %s\n", script, strerror(errno));
    return 127;
}

static int connect_server(void)
{
    const char *path = getenv("DPD_ANALYSE_SOCKET");
    struct sockaddr_un addr = {.sun_family = AF_UNIX};
    if (!path || !*path || strlen(path) >= sizeof addr.sun_path) return -1;
    strcpy(addr.sun_path, path);
    const int fd = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd < 0) return -1;
    if (connect(fd, (struct sockaddr *)&addr, sizeof addr) == 0) return fd;
    close(fd);
    return -1;
}

/* length (4 bytes, little-endian), then cwd and the arguments, each NUL-terminated */
static char *request(int argc, char **argv, size_t *len)
{
    char *cwd = getcwd(NULL, 0);
    if (!cwd) return NULL;
    size_t n = strlen(cwd) + 1;
    for (int i = 1; i < argc; i++) n += strlen(argv[i]) + 1;
    char *buf = n <= UINT32_MAX ? malloc(4 + n) : NULL;
    if (buf) {
        const uint32_t u = (uint32_t)n;
        for (int b = 0; b < 4; b++) buf[b] = (char)((u >> (8 * b)) & 0xff);
        char *p = buf + 4;
        p = stpcpy(p, cwd) + 1;
        for (int i = 1; i < argc; i++) p = stpcpy(p, argv[i]) + 1;
        *len = 4 + n;
    }
    free(cwd);
    return buf;
}

/* the request's first byte carries descriptors 0, 1 and 2; 0 when all of it was sent */
static int send_request(int fd, const char *buf, size_t len)
{
    const int fds[3] = {0, 1, 2};
    union { struct cmsghdr h; char space[CMSG_SPACE(sizeof fds)]; } ctl;
    memset(&ctl, 0, sizeof ctl);
    struct iovec iov = {.iov_base = (void *)buf, .iov_len = len};
    struct msghdr msg = {.msg_iov = &iov, .msg_iovlen = 1, .msg_control = ctl.space, .msg_controllen = sizeof ctl.space};
    struct cmsghdr *c = CMSG_FIRSTHDR(&msg);
    c->cmsg_level = SOL_SOCKET;
    c->cmsg_type = SCM_RIGHTS;
    c->cmsg_len = CMSG_LEN(sizeof fds);
    memcpy(CMSG_DATA(c), fds, sizeof fds);
    ssize_t w;
    do w = sendmsg(fd, &msg, MSG_NOSIGNAL); while (w < 0 && errno == EINTR);
    if (w <= 0) return -1;
    for (size_t off = (size_t)w; off < len; off += (size_t)w) {
        do w = send(fd, buf + off, len - off, MSG_NOSIGNAL); while (w < 0 && errno == EINTR);
        if (w <= 0) return 1;   /* handed over in part: the server sees a call cut short */
    }
    return 0;
}

int main(int argc, char **argv)
{
    for (int i = 0; i < 3; i++)
        if (fcntl(i, F_GETFD) < 0) return fallback(argv);
    const int fd = connect_server();
    if (fd < 0) return fallback(argv);
    size_t len = 0;
    char *buf = request(argc, argv, &len);
    if (!buf) { close(fd); return fallback(argv); }
    const int sent = send_request(fd, buf, len);
    free(buf);
    if (sent < 0) { close(fd); return fallback(argv); }
    unsigned char st[4];
    size_t got = 0;
    while (sent == 0 && got < sizeof st) {
        const ssize_t r = read(fd, st + got, sizeof st - got);
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) break;
        got += (size_t)r;
    }
    close(fd);
    if (got < sizeof st) {
        fprintf(stderr, "analyse-client: the analysis server ended the call '%s' without its status\n", argc > 1 ? argv[1] : "");
        return 70;
    }
    return (int)(st[0] | st[1] << 8 | st[2] << 16 | (unsigned)st[3] << 24);
}
