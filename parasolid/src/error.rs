//! Errors of the reader and the tessellator: each names the file and, where one is at fault,
//! the node (its index in the transmit file and its type).

use std::path::PathBuf;
use thiserror::Error;

/// A node of a transmit file: index and type number (with the type's name where known).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NodeRef {
    /// The node's index in the file (the number written after its type).
    pub index: u32,
    /// The node type number.
    pub node_type: u16,
}

impl std::fmt::Display for NodeRef {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match crate::schema::type_name(self.node_type) {
            Some(name) => write!(f, "node {} ({name}, type {})", self.index, self.node_type),
            None => write!(f, "node {} (type {})", self.index, self.node_type),
        }
    }
}

/// What went wrong, without the file.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ErrorKind {
    /// The file could not be read.
    #[error("cannot read the file: {0}")]
    Io(String),
    /// The text header or the stream's opening is not that of a Parasolid text transmit file.
    #[error("not a Parasolid text transmit file: {0}")]
    NotTransmit(String),
    /// A schema key this reader has no layouts for: neither the base schema 13006 itself nor
    /// changes embedded against it.
    #[error(
        "schema {key}: {why}; only files of schema 13006, or with their changes embedded against 13006 (Parasolid V14 and later), are read — save the part from a newer Parasolid version"
    )]
    UnsupportedSchema {
        /// The key as the file writes it, e.g. `SCH_1200000_12006`.
        key: String,
        /// What about it is not read.
        why: String,
    },
    /// The file ends before the terminator node.
    #[error("the file ends inside {what} (truncated file?)")]
    Truncated {
        /// Where: "the header", or a node and field.
        what: String,
    },
    /// A token is not of the kind the schema says.
    #[error("at line {line}, column {column}: {what}")]
    BadToken {
        /// Line in the file (1-based).
        line: usize,
        /// Column (1-based).
        column: usize,
        /// The node and field being read, and what was found.
        what: String,
    },
    /// A node type that is neither in the base schema nor described by the file.
    #[error(
        "node {index}: node type {node_type} is unknown (not in the base schema and the file does not describe it)"
    )]
    UnknownNodeType {
        /// The node's index.
        index: u32,
        /// The unknown type number.
        node_type: u16,
    },
    /// The embedded schema changes do not fit the base schema.
    #[error("the schema changes for node type {node_type}: {what}")]
    BadSchema {
        /// Node type.
        node_type: u16,
        /// What does not fit.
        what: String,
    },
    /// A pointer field names a node that is not in the file, or one of the wrong type.
    #[error("{node}: field {field} refers to node {target}, {why}")]
    DanglingReference {
        /// The node holding the pointer.
        node: NodeRef,
        /// The field.
        field: &'static str,
        /// The index it holds.
        target: u32,
        /// "which is not in the file" or the type found.
        why: String,
    },
    /// A field the reader needs is missing from the node's layout or unset.
    #[error("{node}: field {field} {why}")]
    MissingField {
        /// The node.
        node: NodeRef,
        /// The field.
        field: &'static str,
        /// "is not in this file's layout" or "is unset".
        why: &'static str,
    },
    /// Geometry the tessellator does not handle, or that is degenerate.
    #[error("{node}: {what}")]
    Geometry {
        /// The node at fault.
        node: NodeRef,
        /// What is wrong.
        what: String,
    },
    /// No body carries the attributes asked for.
    #[error("no body of {part} has AdamsObjectName = {element} (bodies: {known})")]
    BodyNotFound {
        /// The part name asked for.
        part: String,
        /// The ELEMENT name asked for.
        element: String,
        /// The bodies the file has, as part/element.
        known: String,
    },
    /// The mesh made from a body is not a closed, consistently oriented solid.
    #[error("body {body}: the tessellation is not a closed solid: {what}")]
    OpenMesh {
        /// The body's name (part/element) or index.
        body: String,
        /// The faceted engine's mesh check message.
        what: String,
    },
}

/// A reader or tessellator error: the file and what went wrong in it.
#[derive(Debug, Clone, PartialEq, Error)]
#[error("{}: {kind}", file.display())]
pub struct Error {
    /// The transmit file.
    pub file: PathBuf,
    /// What went wrong.
    pub kind: ErrorKind,
}

impl Error {
    /// An error in `file`.
    pub fn new(file: impl Into<PathBuf>, kind: ErrorKind) -> Self {
        Self {
            file: file.into(),
            kind,
        }
    }
}
