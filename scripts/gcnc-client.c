/*
 * The resident checker's client in C: what scripts/gcnc-client.py does, without Python's start-up
 * (some 15-60 ms on this machine, more than checking a 2,000-block program in the warm JVM takes).
 * scripts/install.sh compiles it beside the jar when a C compiler is there (cc -O2); the launcher
 * runs it when it is there, else the Python client. Same protocol (docs/command-line.md, "Resident
 * checker"), same exit statuses: 75 with nothing printed means "run cold".
 *
 * usage: gcnc-client JAR ARG...
 *
 * A frame is one type byte, a big-endian 32-bit length and that many bytes. The request: T token,
 * R, J jar, C working directory, E each NAME=VALUE of the environment, A each argument, O "1" when
 * standard input and output are terminals, S standard output's "dev:ino", I when an argument `-` is
 * the program, G. The daemon answers Y (it runs it) or K/N (run cold), then 1/2 (standard output
 * and error) and X (the status); standard input goes to it as i frames and a closing z, from a
 * thread of its own, while the output comes back.
 */
#define _GNU_SOURCE
#include <arpa/inet.h>
#include <errno.h>
#include <limits.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <unistd.h>

#define COLD 75
#define CHUNK 65536

extern char **environ;

/* The request, built in memory and sent at once (as the Python client does). */
static char *req;
static size_t req_len, req_cap;

static void put(const void *p, size_t n) {
    if (req_len + n > req_cap) {
        req_cap = (req_len + n) * 2 + 4096;
        req = realloc(req, req_cap);
        if (!req) exit(COLD);
    }
    memcpy(req + req_len, p, n);
    req_len += n;
}

static void frame(char kind, const void *data, size_t n) {
    unsigned char head[5];
    uint32_t len = htonl((uint32_t) n);
    head[0] = (unsigned char) kind;
    memcpy(head + 1, &len, 4);
    put(head, 5);
    put(data, n);
}

static void frame_text(char kind, const char *text) {
    frame(kind, text, strlen(text));
}

static int send_all(int fd, const void *p, size_t n) {
    const char *c = p;
    while (n > 0) {
        ssize_t w = send(fd, c, n, MSG_NOSIGNAL);
        if (w < 0) {
            if (errno == EINTR) continue;
            return -1;
        }
        c += w;
        n -= (size_t) w;
    }
    return 0;
}

static int read_exactly(int fd, void *p, size_t n) {
    char *c = p;
    while (n > 0) {
        ssize_t r = recv(fd, c, n, 0);
        if (r == 0) {
            errno = ECONNRESET;
            return -1;
        }
        if (r < 0) {
            if (errno == EINTR) continue;
            return -1;
        }
        c += r;
        n -= (size_t) r;
    }
    return 0;
}

static int write_all(int fd, const char *p, size_t n) {
    while (n > 0) {
        ssize_t w = write(fd, p, n);
        if (w < 0) {
            if (errno == EINTR) continue;
            return -1;
        }
        p += w;
        n -= (size_t) w;
    }
    return 0;
}

/* The folder of daemon.state: GCNC_DAEMON_DIR, else $XDG_RUNTIME_DIR/gcnc, else ~/.cache/gcnc. */
static void state_file(char *out, size_t n) {
    const char *d = getenv("GCNC_DAEMON_DIR");
    const char *x = getenv("XDG_RUNTIME_DIR");
    const char *home = getenv("HOME");
    if (d && *d) snprintf(out, n, "%s/daemon.state", d);
    else if (x && *x) snprintf(out, n, "%s/gcnc/daemon.state", x);
    else snprintf(out, n, "%s/.cache/gcnc/daemon.state", home ? home : "");
}

/* Reads port, token and pid; 0 when the file holds all three. */
static int read_state(const char *path, int *port, char *token, size_t token_n, long *pid) {
    FILE *f = fopen(path, "r");
    char line[1024];
    int got = 0;
    if (!f) return -1;
    while (fgets(line, sizeof line, f)) {
        char *eq = strchr(line, '=');
        size_t l = strlen(line);
        if (l && line[l - 1] == '\n') line[--l] = 0;
        if (!eq) continue;
        *eq = 0;
        if (!strcmp(line, "port")) { *port = atoi(eq + 1); got |= 1; }
        else if (!strcmp(line, "token") && strlen(eq + 1) < token_n) { strcpy(token, eq + 1); got |= 2; }
        else if (!strcmp(line, "pid")) { *pid = atol(eq + 1); got |= 4; }
    }
    fclose(f);
    return got == 7 && *port > 0 ? 0 : -1;
}

/* An argument `-` that is a program, not the value of -o or --svg (those write standard output). */
static int reads_stdin(int argc, char **argv) {
    for (int i = 0; i < argc; i++) {
        if (!strcmp(argv[i], "-") && !(i > 0 && (!strcmp(argv[i - 1], "-o") || !strcmp(argv[i - 1], "--output")
                || !strcmp(argv[i - 1], "--svg")))) {
            return 1;
        }
    }
    return 0;
}

static int sock_fd;

static void *pump_stdin(void *unused) {
    static char buf[CHUNK];
    unsigned char head[5];
    (void) unused;
    for (;;) {
        ssize_t r = read(0, buf, sizeof buf);
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) break;
        uint32_t len = htonl((uint32_t) r);
        head[0] = 'i';
        memcpy(head + 1, &len, 4);
        if (send_all(sock_fd, head, 5) || send_all(sock_fd, buf, (size_t) r)) return NULL;
    }
    memset(head, 0, sizeof head);
    head[0] = 'z';
    send_all(sock_fd, head, 5); /* the run may have ended without reading all of it, as a cold one would */
    return NULL;
}

/* A state file whose daemon is gone (a reboot, a kill): removed, so that later runs skip the client. */
static void forget_dead(const char *path, long pid) {
    if (kill((pid_t) pid, 0) < 0 && errno == ESRCH) unlink(path);
}

int main(int argc, char **argv) {
    char path[PATH_MAX + 32], token[256], jar[PATH_MAX], cwd[PATH_MAX];
    int port = 0;
    long pid = 0;
    if (argc < 2) return COLD;
    state_file(path, sizeof path);
    if (read_state(path, &port, token, sizeof token, &pid)) return COLD;
    if (!realpath(argv[1], jar) || !getcwd(cwd, sizeof cwd)) return COLD;

    sock_fd = socket(AF_INET, SOCK_STREAM, 0);
    if (sock_fd < 0) return COLD;
    struct timeval two = {2, 0};
    setsockopt(sock_fd, SOL_SOCKET, SO_RCVTIMEO, &two, sizeof two);
    setsockopt(sock_fd, SOL_SOCKET, SO_SNDTIMEO, &two, sizeof two);
    struct sockaddr_in at = {0};
    at.sin_family = AF_INET;
    at.sin_port = htons((uint16_t) port);
    at.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (connect(sock_fd, (struct sockaddr *) &at, sizeof at) < 0) {
        if (errno == ECONNREFUSED) forget_dead(path, pid);
        return COLD;
    }
    int one = 1;
    setsockopt(sock_fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);

    int stdin_program = reads_stdin(argc - 2, argv + 2);
    frame_text('T', token);
    frame('R', "", 0);
    frame_text('J', jar);
    frame_text('C', cwd);
    for (char **e = environ; *e; e++) frame_text('E', *e);
    for (int i = 2; i < argc; i++) frame_text('A', argv[i]);
    frame_text('O', isatty(0) && isatty(1) ? "1" : "0");
    struct stat st;
    if (fstat(1, &st) == 0) {
        char id[64];
        snprintf(id, sizeof id, "%lu:%lu", (unsigned long) st.st_dev, (unsigned long) st.st_ino);
        frame_text('S', id);
    }
    if (stdin_program) frame('I', "", 0);
    frame('G', "", 0);
    if (send_all(sock_fd, req, req_len)) return COLD;

    unsigned char head[5];
    uint32_t len;
    if (read_exactly(sock_fd, head, 5)) return COLD;
    memcpy(&len, head + 1, 4);
    len = ntohl(len);
    if (head[0] != 'Y') return COLD; /* K: cold (stale, busy, another folder...), N: refused */
    char *skip = malloc(len + 1);
    if (!skip || read_exactly(sock_fd, skip, len)) return COLD;
    free(skip);
    struct timeval none = {0, 0};
    setsockopt(sock_fd, SOL_SOCKET, SO_RCVTIMEO, &none, sizeof none);
    setsockopt(sock_fd, SOL_SOCKET, SO_SNDTIMEO, &none, sizeof none);

    pthread_t pump;
    if (stdin_program && pthread_create(&pump, NULL, pump_stdin, NULL) == 0) pthread_detach(pump);

    static char buf[CHUNK];
    int printed = 0;
    for (;;) {
        if (read_exactly(sock_fd, head, 5)) break;
        memcpy(&len, head + 1, 4);
        len = ntohl(len);
        char kind = (char) head[0];
        /* K before any output: the run failed inside gcnc, a cold JVM runs it again */
        if (kind == 'K' && !printed) return COLD;
        if (kind == '1' || kind == '2') printed = 1;
        if (kind == 'X') {
            char status[16] = {0};
            if (len >= sizeof status || read_exactly(sock_fd, status, len)) break;
            return atoi(status);
        }
        while (len > 0) {
            size_t n = len < sizeof buf ? len : sizeof buf;
            if (read_exactly(sock_fd, buf, n)) goto broken;
            if (kind == '1') write_all(1, buf, n);
            else if (kind == '2') write_all(2, buf, n);
            len -= (uint32_t) n;
        }
    }
broken:
    {
        char msg[512];
        snprintf(msg, sizeof msg, "gcnc: the resident checker stopped during this run (%s); run it again with "
                 "GCNC_DAEMON=off\n", strerror(errno));
        write_all(2, msg, strlen(msg));
    }
    return 2;
}
