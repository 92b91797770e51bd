"""LSP diagnostics latency (issue 16): a 5,000-line file opened in `lispcad lsp`, then 20
changes (full-text sync, as editors send them); the time from sending each change to receiving
its publishDiagnostics. Usage: python3 lsp_latency.py path/to/lispcad"""
import json, os, subprocess, sys, time
exe = sys.argv[1]
lines = []
for i in range(1000):
    lines += [f";; function {i}", f"(defun f{i} (a b / c)", f"  (setq c (+ a b (f{max(i-1,0)} a b)))", f"  (if (> c 10) (setq glob{i} c))", "  (polar (list a b) c 1.0))"]
text = "\n".join(lines) + "\n"
assert len(lines) == 5000
p = subprocess.Popen([exe, "lsp"], stdin=subprocess.PIPE, stdout=subprocess.PIPE)
def send(m):
    b = json.dumps(m).encode()
    p.stdin.write(b"Content-Length: %d\r\n\r\n" % len(b) + b); p.stdin.flush()
def recv():
    n = None
    while True:
        l = p.stdout.readline().strip()
        if not l: break
        if l.startswith(b"Content-Length:"): n = int(l.split()[1])
    return json.loads(p.stdout.read(n))
send({"jsonrpc":"2.0","id":1,"method":"initialize","params":{"processId":None,"capabilities":{}}}); recv()
send({"jsonrpc":"2.0","method":"initialized","params":{}})
uri = "file:///tmp/lispcad-lsp-latency.lsp"
send({"jsonrpc":"2.0","method":"textDocument/didOpen","params":{"textDocument":{"uri":uri,"languageId":"autolisp","version":1,"text":text}}})
m = recv(); print("open diags", len(m["params"]["diagnostics"]))
def cpu_ms():
    # utime + stime of the server, in clock ticks: its own work, whatever the machine's load.
    f = open(f"/proc/{p.pid}/stat").read().rsplit(")", 1)[1].split()
    return (int(f[11]) + int(f[12])) * 1000.0 / os.sysconf("SC_CLK_TCK")
ts = []
c0 = cpu_ms()
for v in range(2, 22):
    t = text.replace("(+ a b", "(+ a b %d" % v, 1)
    t0 = time.perf_counter()
    send({"jsonrpc":"2.0","method":"textDocument/didChange","params":{"textDocument":{"uri":uri,"version":v},"contentChanges":[{"text":t}]}})
    m = recv()
    ts.append((time.perf_counter()-t0)*1000)
cpu = (cpu_ms() - c0) / 20
ts.sort()
print("change->diagnostics ms: min %.1f median %.1f max %.1f; server CPU per change %.1f ms" % (ts[0], ts[len(ts)//2], ts[-1], cpu))
send({"jsonrpc":"2.0","id":2,"method":"shutdown"}); recv(); send({"jsonrpc":"2.0","method":"exit"}); p.wait()
