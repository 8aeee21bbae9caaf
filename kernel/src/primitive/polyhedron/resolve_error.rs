//! [`ResolveError`]: why a [`super::MeshResolver`] could not provide a mesh, a file or a
//! subdivision, typed across the crate boundary (the resolver's own error stays reachable).

use std::error::Error;
use std::fmt;
use std::sync::Arc;

/// Which request of a resolver failed, and how.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum ResolveKind {
    /// The resolver does not serve this kind of request (the trait's defaults).
    Unsupported,
    /// The named file could not be read: missing, outside the allowed folders, not a regular
    /// file, too large.
    File,
    /// The file was read but does not hold what was asked for (not a mesh of its format).
    Format,
    /// Subdivision refused the mesh (not a manifold, too many faces).
    Subdivision,
}

/// Why a [`super::MeshResolver`] request failed: its [`ResolveKind`] and the resolver's own error
/// (for `solidkit-meshing`'s `FileMeshResolver`, a `MeshIoError` or a subdivision error), whose
/// message is this error's message. [`ResolveError::inner`] gives it for downcasting.
#[derive(Debug, Clone)]
pub struct ResolveError {
    kind: ResolveKind,
    inner: Arc<dyn Error + Send + Sync + 'static>,
}

/// A plain message, for resolvers without a typed error of their own.
#[derive(Debug)]
struct Message(String);

impl fmt::Display for Message {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl Error for Message {}

impl ResolveError {
    /// A failure of `kind` caused by the resolver's error `inner`.
    pub fn new(kind: ResolveKind, inner: impl Error + Send + Sync + 'static) -> Self {
        ResolveError {
            kind,
            inner: Arc::new(inner),
        }
    }

    /// A failure of `kind` described by a one-line `message`.
    pub fn message(kind: ResolveKind, message: impl Into<String>) -> Self {
        Self::new(kind, Message(message.into()))
    }

    /// Which request failed, and how.
    pub fn kind(&self) -> ResolveKind {
        self.kind
    }

    /// The resolver's own error (downcast it to the resolver's error type).
    pub fn inner(&self) -> &(dyn Error + Send + Sync + 'static) {
        self.inner.as_ref()
    }
}

impl fmt::Display for ResolveError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&self.inner, f)
    }
}

/// The message is the inner error's, so it is not repeated as a source (error chains printed
/// cause by cause would say it twice); use [`ResolveError::inner`].
impl Error for ResolveError {}

impl PartialEq for ResolveError {
    fn eq(&self, other: &Self) -> bool {
        self.kind == other.kind && self.to_string() == other.to_string()
    }
}
