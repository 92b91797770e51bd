"""LSP diagnostics latency (issue 16): a 5,000-line file opened in `lispcad lsp`, then 40
edits of one line in its middle; the time from sending each change to receiving its
publishDiagnostics, and the server's CPU time per change.

Usage: python3 lsp_latency.py path/to/lispcad [--full]
  By default each change is a range edit (incremental sync, as editors send it to a server
  announcing TextDocumentSyncKind.Incremental); --full sends the whole text every time."""
import json, os, subprocess, sys, time

exe = sys.argv[1]
full = "--full" in sys.argv[2:]
lines = []
for i in range(1000):
    lines += [f";; function {i}", f"(defun f{i} (a b / c)", f"  (setq c (+ a b (f{max(i-1,0)} a b)))", f"  (if (> c 10) (setq glob{i} c))", "  (polar (list a b) c 1.0))"]
assert len(lines) == 5000
EDITED = 5 * 500 + 2  # the setq line of f500, in the middle of the file
text = "\n".join(lines) + "\n"
p = subprocess.Popen([exe, "lsp"], stdin=subprocess.PIPE, stdout=subprocess.PIPE)


def send(m):
    b = json.dumps(m).encode()
    p.stdin.write(b"Content-Length: %d\r\n\r\n" % len(b) + b)
    p.stdin.flush()


def recv():
    n = None
    while True:
        l = p.stdout.readline().strip()
        if not l:
            break
        if l.startswith(b"Content-Length:"):
            n = int(l.split()[1])
    return json.loads(p.stdout.read(n))


def cpu_ms():
    # utime + stime of the server, in clock ticks: its own work, whatever the machine's load.
    f = open(f"/proc/{p.pid}/stat").read().rsplit(")", 1)[1].split()
    return (int(f[11]) + int(f[12])) * 1000.0 / os.sysconf("SC_CLK_TCK")


send({"jsonrpc": "2.0", "id": 1, "method": "initialize", "params": {"processId": None, "capabilities": {}}})
init = recv()
sync = init["result"]["capabilities"]["textDocumentSync"]
if sync != 2 and not full:
    print("the server announces full sync (%s): sending whole texts" % sync)
    full = True
send({"jsonrpc": "2.0", "method": "initialized", "params": {}})
uri = "file:///tmp/lispcad-lsp-latency.lsp"
t0 = time.perf_counter()
send({"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {"textDocument": {"uri": uri, "languageId": "autolisp", "version": 1, "text": text}}})
m = recv()
print("open: %d diagnostics in %.1f ms" % (len(m["params"]["diagnostics"]), (time.perf_counter() - t0) * 1000))
ts = []
c0 = cpu_ms()
N = 40
prev = lines[EDITED]
for v in range(2, 2 + N):
    new = lines[EDITED].replace("(+ a b", "(+ a b %d" % v, 1)
    if full:
        t = "\n".join(lines[:EDITED] + [new] + lines[EDITED + 1:]) + "\n"
        change = {"text": t}
    else:
        change = {"range": {"start": {"line": EDITED, "character": 0}, "end": {"line": EDITED, "character": len(prev)}}, "text": new}
    prev = new
    t0 = time.perf_counter()
    send({"jsonrpc": "2.0", "method": "textDocument/didChange", "params": {"textDocument": {"uri": uri, "version": v}, "contentChanges": [change]}})
    m = recv()
    ts.append((time.perf_counter() - t0) * 1000)
cpu = (cpu_ms() - c0) / N
assert len(m["params"]["diagnostics"]) == 1000, len(m["params"]["diagnostics"])
ts.sort()
print("%s sync, change->diagnostics ms: min %.1f median %.1f max %.1f; server CPU per change %.1f ms"
      % ("full" if full else "incremental", ts[0], ts[N // 2], ts[-1], cpu))
send({"jsonrpc": "2.0", "id": 2, "method": "shutdown"})
recv()
send({"jsonrpc": "2.0", "method": "exit"})
p.wait()
