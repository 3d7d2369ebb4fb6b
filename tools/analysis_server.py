"""tools/analysis_server.py - one python process that runs an experiment's "$ANALYSE" calls.

An analysis makes hundreds of "$ANALYSE" calls, and each used to start its own python: about 60 ms
of CPU per call on the CI machines (the interpreter's start, then analysis.py imported), most of
it page faults of the new process, against a few milliseconds of analysis. This server starts
once per run.sh (tools/lib/exp.sh, analyse_serve), imports analysis.py once, and runs each call
itself or in a forked child (below); the client (tools/lib/analyse-client.c, build/analyse-client)
hands the server its standard input, output and error (SCM_RIGHTS), its working directory and its
arguments, and exits with the call's status. A child is a fork of the server as it was after the
import, never of an earlier call, so every call starts from the same module state as a fresh
`tools/analyse` would; it writes to the caller's own descriptors, so pipes, redirections and
end-of-file behave as with a process of its own. analysis.py reads no environment variable: the
server's (the experiment's) applies.

Protocol (one connection per call): the client sends a 4-byte little-endian length, then that many
bytes: the working directory and the arguments (subcommand first), each NUL-terminated; the first
part carries descriptors 0, 1 and 2. The server (or its child) answers with the call's exit status,
4 bytes little-endian, after the call's output, and closes. A client that cannot reach the server runs tools/analyse itself.

A call runs in the server itself, without a fork, when nothing of it can wait on another call: its
standard input is not a pipe, a socket or a terminal, and its stdout and stderr are not one file.
That relies on analysis.py keeping no state between calls: no module-level variable that a call
changes, no cache (tests/analysis.py checks its source for them). Its output is kept in memory while it runs (sys.stdout and sys.stderr are StringIOs, sys.stdin
the caller's file), then written to the caller's descriptors with the encoding and error handler
the server's own streams have, as a fork's TextIOWrapper would write them; a write that could block
(a pipe without the room, whose reader may be waiting for this server) is left to a fork. Forks
cost the server about 5 ms of CPU each on the CI machines; most calls take a few hundred
microseconds inline. Any other call (a pipe on stdin: `... | "$ANALYSE" mean-se`) runs in a fork,
as before.

The server ends when the shell that started it has gone (the process it was given to watch), and
removes its socket. It is not that shell's child (exp.sh starts it detached), so that a bare
`wait` in a run.sh does not wait for it. tests/analyse_server.sh checks the outputs, statuses, stdin and concurrency against the
plain tools/analyse.
"""
import fcntl
import gc
import io
import os
import select
import signal
import socket
import stat
import struct
import sys
import termios
import traceback

import analysis


def _status(code):
    """The exit status python gives for sys.exit(code)."""
    if code is None:
        return 0
    if isinstance(code, int):
        return code & 0xff
    sys.stderr.write('%s\n' % code)
    return 1


def _run(argv):
    """One call, as `python -c 'sys.exit(analysis.main(argv))'` runs it: its status."""
    try:
        code = _status(analysis.main(['analyse'] + argv))
    except SystemExit as e:
        code = _status(e.code)
    except BaseException:
        traceback.print_exc()
        code = 1
    # flushed here, as the interpreter does at its exit (a closed pipe: status 120, as python's)
    for f in (sys.stdout, sys.stderr):
        try:
            f.flush()
        except OSError:
            code = 120
    return code


def _request(conn):
    """(cwd, argv, fds) of a call; raises on a malformed one."""
    msg, fds, _, _ = socket.recv_fds(conn, 65536, 3)
    if len(fds) != 3 or len(msg) < 4:
        for fd in fds:
            os.close(fd)
        raise ValueError('a call without its three descriptors')
    (n,) = struct.unpack('<I', msg[:4])
    data = msg[4:]
    while len(data) < n:
        part = conn.recv(n - len(data))
        if not part:
            raise ValueError('a call cut short')
        data += part
    parts = data[:n].split(b'\0')[:-1]
    if not parts:
        raise ValueError('a call without a working directory')
    return os.fsdecode(parts[0]), [os.fsdecode(p) for p in parts[1:]], fds


def _child(conn, cwd, argv, fds):
    """In the forked child: run the call on the client's descriptors, answer its status."""
    signal.signal(signal.SIGCHLD, signal.SIG_DFL)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    for i, fd in enumerate(fds):
        os.dup2(fd, i)
        os.close(fd)
    _answer(conn, _run_in(cwd, argv))
    os._exit(0)


def _run_in(cwd, argv):
    """_run in the caller's working directory (one that cannot be entered: status 1, said)."""
    try:
        os.chdir(cwd)
        return _run(argv)
    except OSError as e:
        sys.stderr.write('analyse: %s: %s\n' % (cwd, e))
        return 1


def _answer(conn, code):
    """The call's status to the client (gone: nothing to tell)."""
    try:
        conn.sendall(struct.pack('<I', code))
    except OSError:
        pass


# the encodings and error handlers of the server's own streams (a fork writes through them)
_ENC = [(f.encoding, f.errors) for f in (sys.stdout, sys.stderr)]


def _inline(fds):
    """Whether a call on these descriptors (stdin, stdout, stderr) can run in the server: no input
    that another call may be writing (a pipe, a socket) or that a user types (a terminal), and
    stdout and stderr not one file (their order would change)."""
    try:
        st = [os.fstat(fd) for fd in fds]
    except OSError:
        return False
    m = st[0].st_mode
    if stat.S_ISFIFO(m) or stat.S_ISSOCK(m) or os.isatty(fds[0]):
        return False
    return (st[1].st_dev, st[1].st_ino) != (st[2].st_dev, st[2].st_ino)


def _fits(fd, n):
    """A blocking write of n bytes to fd cannot wait on a reader: fd is not a pipe or socket, or
    the pipe has room for them now."""
    m = os.fstat(fd).st_mode
    if stat.S_ISSOCK(m):
        return False
    if not stat.S_ISFIFO(m):
        return True
    try:
        size = fcntl.fcntl(fd, 1032)   # F_GETPIPE_SZ
        queued = struct.unpack('i', fcntl.ioctl(fd, termios.FIONREAD, b'\0\0\0\0'))[0]
    except OSError:
        return False
    return queued + n <= size


def _write_all(fd, data):
    while data:
        data = data[os.write(fd, data):]


def _serve_inline(sock, conn, cwd, argv, fds):
    """Run one call in the server (_inline said it may), write its output, answer its status."""
    out, err = io.StringIO(), io.StringIO()
    saved = sys.stdin, sys.stdout, sys.stderr
    stdin = None
    try:
        stdin = open(fds[0], 'r', closefd=False, encoding=sys.stdin.encoding, errors=sys.stdin.errors)
        sys.stdin, sys.stdout, sys.stderr = stdin, out, err
        code = _run_in(cwd, argv)
    finally:
        sys.stdin, sys.stdout, sys.stderr = saved
        if stdin is not None:
            stdin.close()
        os.chdir('/')
    data = [buf.getvalue().encode(enc, errors) for buf, (enc, errors) in zip((out, err), _ENC)]
    if not all(_fits(fd, len(d)) for fd, d in zip(fds[1:], data)):
        # a reader that may be a call waiting for this server: a fork writes it
        try:
            pid = os.fork()
        except OSError:
            pid = -1
        if pid == 0:
            try:
                sock.close()
                _finish(conn, fds, data, code)
            finally:
                os._exit(0)
        if pid > 0:
            _close(conn, fds)
            return
    _finish(conn, fds, data, code)
    _close(conn, fds)


def _finish(conn, fds, data, code):
    """The call's output to its descriptors (a closed reader: status 120, as python's), its status."""
    for fd, d in zip(fds[1:], data):
        try:
            _write_all(fd, d)
        except OSError:
            code = 120
    _answer(conn, code)


def _close(conn, fds):
    for fd in fds:
        try:
            os.close(fd)
        except OSError:
            pass
    conn.close()


def _start_time(pid):
    """The process's start time (/proc/PID/stat field 22), None if it has none: a PID that the
    kernel gives to another process later has another."""
    try:
        with open('/proc/%d/stat' % pid, 'rb') as f:
            return f.read().rsplit(b')', 1)[1].split()[19]
    except (OSError, IndexError):
        return None


def _alive(pid, started):
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        pass
    return started is None or _start_time(pid) == started


def serve(path, watch):
    """Serve on the socket PATH while the process WATCH (the shell of the run.sh) lives."""
    os.closerange(3, 1 << 16)   # none of the caller's pipes or make's jobserver kept open
    started = _start_time(watch)
    sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    sock.bind(path)
    sock.listen(64)
    # ready: the caller reads this line, then every descriptor it lent is given back (the
    # server must not keep a pipe of the caller open, e.g. make's output or a tee)
    sys.stdout.write('ready\n')
    sys.stdout.flush()
    null = os.open(os.devnull, os.O_RDWR)
    for i in range(3):
        os.dup2(null, i)
    os.close(null)
    os.chdir('/')
    signal.signal(signal.SIGCHLD, signal.SIG_IGN)   # the children are reaped by the kernel
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(0))
    gc.collect()
    gc.freeze()   # the objects of the import are not touched by the children's collections
    try:
        while _alive(watch, started):
            if not select.select([sock], [], [], 1.0)[0]:
                continue
            try:
                conn, _ = sock.accept()
            except OSError:
                continue
            try:
                conn.settimeout(10.0)   # the client sends its call at once
                cwd, argv, fds = _request(conn)
                conn.settimeout(None)
            except (OSError, ValueError):
                conn.close()   # the client sees no status and says so
                continue
            if _inline(fds):
                try:
                    _serve_inline(sock, conn, cwd, argv, fds)
                except Exception:   # (not the server's end: the client sees no status and says so)
                    _close(conn, fds)
                continue
            try:
                pid = os.fork()
            except OSError:
                _close(conn, fds)   # the client sees no status and says so
                continue
            if pid == 0:
                try:
                    sock.close()
                    _child(conn, cwd, argv, fds)
                finally:
                    os._exit(1)   # never back into the server's loop
            _close(conn, fds)
    finally:
        try:
            os.unlink(path)
            os.rmdir(os.path.dirname(path))
        except OSError:
            pass
    return 0
