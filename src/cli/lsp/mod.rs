//! `lispcad lsp`: a language server over stdio (LSP 3.17). One main loop over incoming
//! messages, a dispatcher by method name, and the pure functions of `features` computing each
//! answer from the latest snapshot of a document.

pub mod document;
pub mod features;
mod lex;
mod vars;

use std::collections::HashMap;

use lsp_server::{Connection, ErrorCode, Message, Notification, Request, Response};
use lsp_types::notification::{
    DidChangeTextDocument, DidCloseTextDocument, DidOpenTextDocument, DidSaveTextDocument,
    Notification as _, PublishDiagnostics,
};
use lsp_types::request::{
    Completion, DocumentSymbolRequest, FoldingRangeRequest, GotoDefinition, HoverRequest,
    Request as _,
};
use lsp_types::{
    CompletionOptions, DocumentSymbolResponse, FoldingRangeProviderCapability,
    HoverProviderCapability, InitializeParams, OneOf, PublishDiagnosticsParams, ServerCapabilities,
    ServerInfo, TextDocumentSyncCapability, TextDocumentSyncKind, Uri,
};
use serde::de::DeserializeOwned;
use serde::Serialize;

use document::Document;

use crate::lang::Interp;

type Error = Box<dyn std::error::Error + Send + Sync>;

pub fn lsp() -> i32 {
    match serve() {
        Ok(()) => super::EXIT_OK,
        Err(e) => {
            eprintln!("lispcad lsp: {e}");
            super::EXIT_SCRIPT_ERROR
        }
    }
}

pub fn capabilities() -> ServerCapabilities {
    ServerCapabilities {
        text_document_sync: Some(TextDocumentSyncCapability::Kind(
            TextDocumentSyncKind::INCREMENTAL,
        )),
        hover_provider: Some(HoverProviderCapability::Simple(true)),
        completion_provider: Some(CompletionOptions {
            trigger_characters: Some(vec!["(".into()]),
            ..Default::default()
        }),
        definition_provider: Some(OneOf::Left(true)),
        document_symbol_provider: Some(OneOf::Left(true)),
        folding_range_provider: Some(FoldingRangeProviderCapability::Simple(true)),
        ..Default::default()
    }
}

fn serve() -> Result<(), Error> {
    let (connection, io_threads) = Connection::stdio();
    let (id, params) = connection.initialize_start()?;
    let _params: InitializeParams = serde_json::from_value(params)?;
    let result = lsp_types::InitializeResult {
        capabilities: capabilities(),
        server_info: Some(ServerInfo {
            name: "lispcad".into(),
            version: Some(env!("CARGO_PKG_VERSION").into()),
        }),
    };
    connection.initialize_finish(id, serde_json::to_value(result)?)?;
    main_loop(&connection)?;
    drop(connection);
    io_threads.join()?;
    Ok(())
}

/// The open documents and the interpreter whose symbol table and builtins the analyses use.
struct State {
    it: Interp,
    docs: HashMap<String, Document>,
}

fn main_loop(conn: &Connection) -> Result<(), Error> {
    let mut st = State {
        it: crate::builtins::new_interp(),
        docs: HashMap::new(),
    };
    // Documents changed since their diagnostics were last published. They are published once
    // the queue is empty: a burst of keystrokes is analysed once, for its last text.
    let mut dirty: Vec<Uri> = Vec::new();
    for msg in &conn.receiver {
        match msg {
            Message::Request(req) => {
                if conn.handle_shutdown(&req)? {
                    return Ok(());
                }
                let resp = handle_request(&mut st, req);
                conn.sender.send(Message::Response(resp))?;
            }
            Message::Notification(n) => {
                if let Some(uri) = handle_notification(&mut st, n)? {
                    if !dirty.iter().any(|u| u.as_str() == uri.as_str()) {
                        dirty.push(uri);
                    }
                }
            }
            Message::Response(_) => {}
        }
        if conn.receiver.is_empty() {
            for uri in dirty.drain(..) {
                publish(conn, &mut st, uri)?;
            }
        }
    }
    Ok(())
}

/// Applies a document notification; the URI whose diagnostics are to be published.
fn handle_notification(st: &mut State, n: Notification) -> Result<Option<Uri>, Error> {
    match n.method.as_str() {
        DidOpenTextDocument::METHOD => {
            let p: lsp_types::DidOpenTextDocumentParams = serde_json::from_value(n.params)?;
            let uri = p.text_document.uri;
            let doc = Document::new(
                &mut st.it,
                p.text_document.text,
                features::uri_to_path(&uri),
            );
            st.docs.insert(uri.to_string(), doc);
            Ok(Some(uri))
        }
        DidChangeTextDocument::METHOD => {
            let p: lsp_types::DidChangeTextDocumentParams = serde_json::from_value(n.params)?;
            let uri = p.text_document.uri;
            let Some(doc) = st.docs.get_mut(uri.as_str()) else {
                return Ok(None);
            };
            doc.apply(&mut st.it, p.content_changes);
            Ok(Some(uri))
        }
        // A saved file may be one another document loads: recheck on save.
        DidSaveTextDocument::METHOD => {
            let p: lsp_types::DidSaveTextDocumentParams = serde_json::from_value(n.params)?;
            Ok(Some(p.text_document.uri))
        }
        DidCloseTextDocument::METHOD => {
            let p: lsp_types::DidCloseTextDocumentParams = serde_json::from_value(n.params)?;
            st.docs.remove(p.text_document.uri.as_str());
            Ok(None)
        }
        _ => Ok(None),
    }
}

fn publish(conn: &Connection, st: &mut State, uri: Uri) -> Result<(), Error> {
    let Some(doc) = st.docs.get(uri.as_str()) else {
        return Ok(());
    };
    let diagnostics = features::diagnostics(&mut st.it, doc);
    let params = PublishDiagnosticsParams {
        uri,
        diagnostics,
        version: None,
    };
    conn.sender.send(Message::Notification(Notification::new(
        PublishDiagnostics::METHOD.into(),
        params,
    )))?;
    Ok(())
}

/// Dispatches a request by method; an unknown method or unopened document is an error reply.
fn handle_request(st: &mut State, req: Request) -> Response {
    let id = req.id.clone();
    let result = match req.method.as_str() {
        HoverRequest::METHOD => {
            on::<HoverRequest, _, _>(st, req, |it, s, _, p: lsp_types::HoverParams| {
                features::hover(it, s, p.text_document_position_params.position)
            })
        }
        Completion::METHOD => {
            on::<Completion, _, _>(st, req, |it, s, _, p: lsp_types::CompletionParams| {
                features::completion(it, s, p.text_document_position.position)
            })
        }
        GotoDefinition::METHOD => {
            on::<GotoDefinition, _, _>(st, req, |it, s, uri, p: lsp_types::GotoDefinitionParams| {
                features::definition(it, s, uri, p.text_document_position_params.position)
            })
        }
        DocumentSymbolRequest::METHOD => on::<DocumentSymbolRequest, _, _>(
            st,
            req,
            |it, s, _, _: lsp_types::DocumentSymbolParams| {
                DocumentSymbolResponse::Nested(features::document_symbols(it, s))
            },
        ),
        FoldingRangeRequest::METHOD => {
            on::<FoldingRangeRequest, _, _>(st, req, |_, s, _, _: lsp_types::FoldingRangeParams| {
                features::folding_ranges(s)
            })
        }
        m => Err((ErrorCode::MethodNotFound, format!("unhandled method {m}"))),
    };
    match result {
        Ok(v) => Response::new_ok(id, v),
        Err((code, msg)) => Response::new_err(id, code as i32, msg),
    }
}

/// Decodes a request's params, finds its document and runs `f` on the snapshot.
fn on<R, T, F>(st: &mut State, req: Request, f: F) -> Result<serde_json::Value, (ErrorCode, String)>
where
    R: lsp_types::request::Request,
    T: Serialize,
    F: FnOnce(&mut Interp, &Document, &Uri, R::Params) -> T,
    R::Params: DeserializeOwned + HasDocument,
{
    let params: R::Params = serde_json::from_value(req.params)
        .map_err(|e| (ErrorCode::InvalidParams, e.to_string()))?;
    let uri = params.document().clone();
    let snap = st.docs.get(uri.as_str()).ok_or((
        ErrorCode::InvalidParams,
        format!("{} is not open", uri.as_str()),
    ))?;
    let answer = f(&mut st.it, snap, &uri, params);
    serde_json::to_value(answer).map_err(|e| (ErrorCode::InternalError, e.to_string()))
}

/// The document a request is about.
trait HasDocument {
    fn document(&self) -> &Uri;
}

impl HasDocument for lsp_types::HoverParams {
    fn document(&self) -> &Uri {
        &self.text_document_position_params.text_document.uri
    }
}
impl HasDocument for lsp_types::CompletionParams {
    fn document(&self) -> &Uri {
        &self.text_document_position.text_document.uri
    }
}
impl HasDocument for lsp_types::GotoDefinitionParams {
    fn document(&self) -> &Uri {
        &self.text_document_position_params.text_document.uri
    }
}
impl HasDocument for lsp_types::DocumentSymbolParams {
    fn document(&self) -> &Uri {
        &self.text_document.uri
    }
}
impl HasDocument for lsp_types::FoldingRangeParams {
    fn document(&self) -> &Uri {
        &self.text_document.uri
    }
}
