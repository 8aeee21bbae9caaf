//! Errors of the kernel: invalid trees and unreadable tree files.

/// Why a tree cannot be built or used.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum KernelError {
    /// A node has a bad parameter or the wrong number of children.
    #[error("{path}: {problem}")]
    InvalidNode {
        /// Where the node is, from the root (`children[3].child`), or `root`.
        path: String,
        /// What is wrong.
        problem: String,
    },
    /// A JSON tree that cannot be read.
    #[error("{line}:{column}: {message}")]
    Json {
        /// 1-based line of the offending text.
        line: usize,
        /// 1-based column (in characters) of the offending text.
        column: usize,
        /// What is wrong, with the JSON path of the node where it applies.
        message: String,
    },
}
