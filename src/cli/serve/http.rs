//! The preview's HTTP side (tiny_http, one thread per request): every handler reads the latest
//! publication and nothing else.

use std::io::Write;
use std::net::SocketAddr;
use std::sync::Arc;
use std::time::Duration;

use glam::DVec3;
use tiny_http::{Header, Method, Request, Response, Server};

use super::{Published, Shared};

const PAGE: &str = include_str!("page.html");

/// Listens on 127.0.0.1:`port` (loopback only: the preview runs the user's code's results,
/// nobody else's business) and serves from a background thread; the bound address.
pub fn start(port: u16, shared: Arc<Shared>) -> std::io::Result<SocketAddr> {
    let server = Server::http(("127.0.0.1", port)).map_err(std::io::Error::other)?;
    let addr = server
        .server_addr()
        .to_ip()
        .ok_or_else(|| std::io::Error::other("not an IP listener"))?;
    std::thread::Builder::new()
        .name("lispcad-serve".into())
        .spawn(move || {
            for req in server.incoming_requests() {
                let shared = shared.clone();
                let _ = std::thread::Builder::new()
                    .name("lispcad-serve-req".into())
                    .spawn(move || handle(req, &shared));
            }
        })?;
    Ok(addr)
}

fn header(name: &str, value: &str) -> Header {
    Header::from_bytes(name.as_bytes(), value.as_bytes()).expect("static header is valid")
}

fn handle(req: Request, shared: &Shared) {
    if req.method() != &Method::Get && req.method() != &Method::Head {
        let _ = req.respond(Response::from_string("only GET\n").with_status_code(405));
        return;
    }
    let url = req.url().to_string();
    let (path, query) = url.split_once('?').unwrap_or((&url, ""));
    let text = |body: String, ty: &str| {
        Response::from_string(body)
            .with_header(header("Content-Type", ty))
            .with_header(header("Cache-Control", "no-store"))
    };
    let r = match path {
        "/" | "/index.html" => req.respond(text(PAGE.to_string(), "text/html; charset=utf-8")),
        "/drawing.svg" => {
            let p = shared.latest();
            match svg(&p, query) {
                Ok(s) => req.respond(text(s, "image/svg+xml")),
                Err(m) => req.respond(text(m, "text/plain; charset=utf-8").with_status_code(400)),
            }
        }
        "/status" => req.respond(text(status(&shared.latest()), "application/json")),
        "/events" => {
            events(req, shared);
            Ok(())
        }
        _ => req.respond(text("not found\n".into(), "text/plain").with_status_code(404)),
    };
    let _ = r;
}

/// The drawing as SVG, seen from VIEWDIR or from `?view=x,y,z`.
fn svg(p: &Published, query: &str) -> Result<String, String> {
    let mut opts = p.options.clone();
    for kv in query.split('&') {
        if let Some(v) = kv.strip_prefix("view=") {
            let c: Vec<f64> = v
                .split(',')
                .map(|x| x.trim().parse::<f64>())
                .collect::<Result<_, _>>()
                .map_err(|_| format!("view={v}: expected x,y,z\n"))?;
            let d = match c[..] {
                [x, y, z] => DVec3::new(x, y, z),
                _ => return Err(format!("view={v}: expected x,y,z\n")),
            };
            if !d.is_finite() || d.length() < 1e-12 {
                return Err(format!("view={v}: not a direction\n"));
            }
            opts.view_dir = d;
        }
    }
    Ok(crate::output::svg::write_svg(&p.drawing, &opts))
}

/// Whether any entity leaves the XY plane (the page then offers an orbit).
fn is_3d(p: &Published) -> bool {
    if p.options.view_dir.normalize_or_zero() != DVec3::Z {
        return true;
    }
    let mut pts = Vec::new();
    p.drawing.entities().any(|e| {
        pts.clear();
        e.kind.extent_points(&mut pts);
        pts.iter().any(|q| q.z.abs() > 1e-9)
    })
}

/// `{"ok", "error", "runs"}` as SPEC §9, plus what the page shows: the diagnostic's parts,
/// whether the drawing is 3D and its view direction.
pub fn status(p: &Published) -> String {
    let diagnostic = p.error.as_ref().map(|f| {
        serde_json::json!({
            "message": f.message, "file": f.file, "line": f.line, "column": f.column,
            "snippet": f.snippet,
        })
    });
    let v = p.options.view_dir;
    serde_json::json!({
        "ok": p.error.is_none(),
        "error": p.error.as_ref().map(|f| f.summary()),
        "runs": p.runs,
        "diagnostic": diagnostic,
        "is3d": is_3d(p),
        "view_dir": [v.x, v.y, v.z],
    })
    .to_string()
}

/// Server-Sent Events: one `run` event (the status JSON) per publication after the client
/// connected, and a comment every 15 s so a closed page's thread notices and ends.
fn events(req: Request, shared: &Shared) {
    let mut seen = shared.latest().runs;
    let mut w = req.into_writer();
    let head = "HTTP/1.1 200 OK\r\nContent-Type: text/event-stream\r\nCache-Control: no-store\r\n\
                Connection: keep-alive\r\n\r\n: lispcad\n\n";
    if w.write_all(head.as_bytes())
        .and_then(|_| w.flush())
        .is_err()
    {
        return;
    }
    loop {
        let msg = match shared.wait_after(seen, Duration::from_secs(15)) {
            Some(p) => {
                seen = p.runs;
                format!("event: run\nid: {}\ndata: {}\n\n", p.runs, status(&p))
            }
            None => ": ping\n\n".to_string(),
        };
        if w.write_all(msg.as_bytes()).and_then(|_| w.flush()).is_err() {
            return;
        }
    }
}
