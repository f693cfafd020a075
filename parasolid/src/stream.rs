//! The node stream: every node of a text transmit file read by its type's layout.
//!
//! Each node is its type, then (for a variable-length type) the tail's length, then its
//! index, then its fields; a type's first node is preceded by its layout (`255` for the base
//! layout, otherwise the file's changes, see [`crate::schema`]) unless the file is of the base
//! schema itself ([`Form::Base`]). A file with user fields (size n > 0) writes n integers after
//! every node. The stream ends with the terminator: type 1, index 0.

use crate::error::{ErrorKind, NodeRef};
use crate::schema::{Count, Field, Form, Kind, Layout, base_layout};
use crate::text::{Cursor, Stream, TokenError};
use std::collections::HashMap;
use std::sync::Arc;

/// One field value.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    /// Unset (`?`).
    Unset,
    /// An integer or pointer.
    Int(i64),
    /// A real.
    Real(f64),
    /// A character or logical.
    Char(u8),
    /// A vector.
    Vector([f64; 3]),
    /// Several reals (an interval, a box, a fixed or variable real array).
    Reals(Vec<f64>),
    /// Several integers or pointers.
    Ints(Vec<i64>),
    /// Several vectors (a variable vector tail; unset ones are NaN).
    Vectors(Vec<[f64; 3]>),
    /// Characters (a variable character tail, or a fixed character array).
    Text(String),
}

/// A node: its type, index and field values in its layout's order.
#[derive(Debug, Clone)]
pub struct Node {
    /// The node type number.
    pub node_type: u16,
    /// The node's index in the file.
    pub index: u32,
    /// The layout it was read with.
    pub layout: Arc<Layout>,
    /// Field values, one per layout field.
    pub values: Vec<Value>,
}

impl Node {
    /// The node's reference for messages.
    pub fn reference(&self) -> NodeRef {
        NodeRef {
            index: self.index,
            node_type: self.node_type,
        }
    }

    /// The value of field `name`, if the layout has it.
    pub fn get(&self, name: &str) -> Option<&Value> {
        self.layout.position(name).map(|i| &self.values[i])
    }
}

/// The header of the stream and every node, by index.
#[derive(Debug, Clone)]
pub struct Nodes {
    /// The modeller banner (": TRANSMIT FILE created by modeller version …").
    pub banner: String,
    /// The schema key, e.g. `SCH_3101206_31100_13006`.
    pub schema: String,
    /// The user field size: integers written after every node.
    pub user_fields: usize,
    /// Nodes by index.
    pub by_index: HashMap<u32, Node>,
}

struct Reader<'a> {
    cur: Cursor<'a>,
    layouts: HashMap<u16, Arc<Layout>>,
    form: Form,
    user_fields: usize,
}

/// Where a read failed: the current node, for messages.
#[derive(Clone, Copy)]
struct At<'f> {
    node_type: u16,
    index: Option<u32>,
    field: &'f str,
}

impl std::fmt::Display for At<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let name = crate::schema::type_name(self.node_type)
            .map(|n| format!("{n}, "))
            .unwrap_or_default();
        match self.index {
            Some(i) => write!(
                f,
                "node {i} ({name}type {}), field {}",
                self.node_type, self.field
            ),
            None => write!(
                f,
                "a node of type {} ({name}{})",
                self.node_type, self.field
            ),
        }
    }
}

impl Reader<'_> {
    fn fail(&self, e: TokenError, at: At<'_>) -> ErrorKind {
        match e {
            TokenError::Eof => ErrorKind::Truncated {
                what: at.to_string(),
            },
            TokenError::Bad(offset) => {
                let (line, column) = self.cur.stream().location(offset);
                ErrorKind::BadToken {
                    line,
                    column,
                    what: format!("{at}: not a valid value"),
                }
            }
        }
    }

    fn int(&mut self, at: At<'_>) -> Result<i64, ErrorKind> {
        let offset = self.cur.offset();
        match self.cur.int() {
            Ok(Some(v)) => Ok(v),
            Ok(None) => Err(self.fail(TokenError::Bad(offset), at)),
            Err(e) => Err(self.fail(e, at)),
        }
    }

    fn count(&mut self, at: At<'_>) -> Result<usize, ErrorKind> {
        let offset = self.cur.offset();
        let v = self.int(at)?;
        // A count beyond the bytes left cannot be honest; refuse it before allocating.
        usize::try_from(v)
            .ok()
            .filter(|&n| n <= 1 << 26)
            .ok_or_else(|| self.fail(TokenError::Bad(offset), at))
    }

    fn real(&mut self, at: At<'_>) -> Result<f64, ErrorKind> {
        match self.cur.real() {
            Ok(Some(v)) => Ok(v),
            Ok(None) => Ok(f64::NAN),
            Err(e) => Err(self.fail(e, at)),
        }
    }

    fn vector(&mut self, at: At<'_>) -> Result<Option<[f64; 3]>, ErrorKind> {
        if self.cur.unset().map_err(|e| self.fail(e, at))? {
            return Ok(None);
        }
        Ok(Some([self.real(at)?, self.real(at)?, self.real(at)?]))
    }

    fn one(&mut self, kind: Kind, at: At<'_>) -> Result<Value, ErrorKind> {
        Ok(match kind {
            Kind::Int | Kind::Pointer => match self.cur.int() {
                Ok(Some(v)) => Value::Int(v),
                Ok(None) => Value::Unset,
                Err(e) => return Err(self.fail(e, at)),
            },
            Kind::Real => match self.cur.real() {
                Ok(Some(v)) => Value::Real(v),
                Ok(None) => Value::Unset,
                Err(e) => return Err(self.fail(e, at)),
            },
            Kind::Char => Value::Char(self.cur.char().map_err(|e| self.fail(e, at))?),
            Kind::Vector => match self.vector(at)? {
                Some(v) => Value::Vector(v),
                None => Value::Unset,
            },
            Kind::Interval => Value::Reals(vec![self.real(at)?, self.real(at)?]),
            Kind::Box => Value::Reals((0..6).map(|_| self.real(at)).collect::<Result<_, _>>()?),
        })
    }

    fn many(&mut self, kind: Kind, n: usize, at: At<'_>) -> Result<Value, ErrorKind> {
        Ok(match kind {
            Kind::Int | Kind::Pointer => {
                Value::Ints((0..n).map(|_| self.int(at)).collect::<Result<_, _>>()?)
            }
            Kind::Real => Value::Reals((0..n).map(|_| self.real(at)).collect::<Result<_, _>>()?),
            Kind::Char => {
                if n == 0 {
                    Value::Text(String::new())
                } else {
                    Value::Text(self.cur.raw(n).map_err(|e| self.fail(e, at))?)
                }
            }
            Kind::Vector => Value::Vectors(
                (0..n)
                    .map(|_| Ok(self.vector(at)?.unwrap_or([f64::NAN; 3])))
                    .collect::<Result<_, ErrorKind>>()?,
            ),
            Kind::Interval | Kind::Box => {
                let per = if kind == Kind::Interval { 2 } else { 6 };
                Value::Reals(
                    (0..n * per)
                        .map(|_| self.real(at))
                        .collect::<Result<_, _>>()?,
                )
            }
        })
    }

    /// A field described in the file.
    fn described_field(&mut self, node_type: u16) -> Result<Field, ErrorKind> {
        let at = At {
            node_type,
            index: None,
            field: "its layout",
        };
        let name = self.cur.string().map_err(|e| self.fail(e, at))?;
        let class = self.int(at)?;
        let elements = self.int(at)?;
        let kind = if class == 0 {
            let letter = self.cur.string().map_err(|e| self.fail(e, at))?;
            Kind::from_letter(&letter).ok_or_else(|| ErrorKind::BadSchema {
                node_type,
                what: format!("field {name} has unknown type letter {letter:?}"),
            })?
        } else {
            Kind::Pointer
        };
        let count = match elements {
            0 => Count::One,
            1 => match self.cur.char().map_err(|e| self.fail(e, at))? {
                b'T' => Count::Variable,
                _ => Count::One,
            },
            n if n > 1 => Count::Fixed(n as usize),
            n => {
                return Err(ErrorKind::BadSchema {
                    node_type,
                    what: format!("field {name} has element count {n}"),
                });
            }
        };
        Ok(Field { name, kind, count })
    }

    /// The layout announced at a type's first node.
    fn layout(&mut self, node_type: u16) -> Result<Arc<Layout>, ErrorKind> {
        let at = At {
            node_type,
            index: None,
            field: "its layout",
        };
        let n = self.int(at)?;
        let base = base_layout(node_type);
        let layout = if n == 255 {
            base.ok_or(ErrorKind::UnknownNodeType {
                index: 0,
                node_type,
            })?
        } else if self
            .cur
            .peek()
            .map_err(|e| self.fail(e, at))?
            .is_ascii_digit()
        {
            // A whole description: name, description, fields.
            self.cur.string().map_err(|e| self.fail(e, at))?;
            self.cur.string().map_err(|e| self.fail(e, at))?;
            let fields = (0..n)
                .map(|_| self.described_field(node_type))
                .collect::<Result<_, _>>()?;
            Layout { fields }
        } else {
            let base = base.ok_or(ErrorKind::UnknownNodeType {
                index: 0,
                node_type,
            })?;
            self.edited(node_type, &base, n)?
        };
        let layout = Arc::new(layout);
        self.layouts.insert(node_type, layout.clone());
        Ok(layout)
    }

    fn edited(&mut self, node_type: u16, base: &Layout, n: i64) -> Result<Layout, ErrorKind> {
        let at = At {
            node_type,
            index: None,
            field: "its layout changes",
        };
        let bad = |what: String| ErrorKind::BadSchema { node_type, what };
        let mut old = base.fields.iter();
        let mut fields = Vec::new();
        loop {
            match self.cur.char().map_err(|e| self.fail(e, at))? {
                b'Z' => break,
                b'C' => fields.push(
                    old.next()
                        .ok_or_else(|| bad("copies past the base layout's end".into()))?
                        .clone(),
                ),
                b'D' => {
                    old.next()
                        .ok_or_else(|| bad("deletes past the base layout's end".into()))?;
                }
                b'I' | b'A' => fields.push(self.described_field(node_type)?),
                c => return Err(bad(format!("unknown change {:?}", c as char))),
            }
        }
        if old.next().is_some() {
            return Err(bad("leaves base fields neither copied nor deleted".into()));
        }
        if fields.len() as i64 != n {
            return Err(bad(format!(
                "announces {n} fields but gives {}",
                fields.len()
            )));
        }
        Ok(Layout { fields })
    }

    fn node(&mut self, node_type: u16) -> Result<Node, ErrorKind> {
        let layout = match self.layouts.get(&node_type) {
            Some(l) => l.clone(),
            None if self.form == Form::Base => match base_layout(node_type) {
                Some(l) => {
                    let l = Arc::new(l);
                    self.layouts.insert(node_type, l.clone());
                    l
                }
                None => {
                    let index = self.cur.int().ok().flatten().unwrap_or(0) as u32;
                    return Err(ErrorKind::UnknownNodeType { index, node_type });
                }
            },
            None => self.layout(node_type).map_err(|e| match e {
                ErrorKind::UnknownNodeType { node_type, .. } => {
                    // Name the node: its index is the next integer after the layout.
                    let index = self.cur.int().ok().flatten().unwrap_or(0) as u32;
                    ErrorKind::UnknownNodeType { index, node_type }
                }
                e => e,
            })?,
        };
        let mut at = At {
            node_type,
            index: None,
            field: "its length",
        };
        let tail = if layout.is_variable() {
            self.count(at)?
        } else {
            0
        };
        at.field = "its index";
        let index = self.int(at)?;
        let index = u32::try_from(index).map_err(|_| {
            let (line, column) = self.cur.stream().location(self.cur.offset());
            ErrorKind::BadToken {
                line,
                column,
                what: format!("a node of type {node_type} has index {index}"),
            }
        })?;
        at.index = Some(index);
        let mut values = Vec::with_capacity(layout.fields.len());
        for f in &layout.fields {
            at.field = &f.name;
            values.push(match f.count {
                Count::One => self.one(f.kind, at)?,
                Count::Fixed(n) => self.many(f.kind, n, at)?,
                Count::Variable => self.many(f.kind, tail, at)?,
            });
        }
        at.field = "its user fields";
        for _ in 0..self.user_fields {
            self.int(at)?;
        }
        Ok(Node {
            node_type,
            index,
            layout,
            values,
        })
    }
}

/// Reads the whole node stream.
pub fn read(stream: &Stream) -> Result<Nodes, ErrorKind> {
    let mut r = Reader {
        cur: stream.cursor(),
        layouts: HashMap::new(),
        form: Form::Base,
        user_fields: 0,
    };
    let head = At {
        node_type: 0,
        index: None,
        field: "the stream's opening",
    };
    let t = r.cur.char().map_err(|e| r.fail(e, head))?;
    if t != b'T' {
        return Err(ErrorKind::NotTransmit(format!(
            "the stream starts with {:?}, not T (a binary file is not read)",
            t as char
        )));
    }
    let banner = r.cur.string().map_err(|e| r.fail(e, head))?;
    let schema = r.cur.string().map_err(|e| r.fail(e, head))?;
    if !schema.starts_with("SCH_") {
        return Err(ErrorKind::NotTransmit(format!("schema key {schema:?}")));
    }
    r.form = Form::of(&schema)?;
    if r.form == Form::Embedded {
        // The highest node type the writer knows.
        r.int(head)?;
    }
    r.user_fields = r.count(At {
        field: "the user field size",
        ..head
    })?;
    let mut by_index = HashMap::new();
    loop {
        let at = At {
            node_type: 0,
            index: None,
            field: "the next node's type",
        };
        let t = r.int(at)?;
        if t == 1 {
            r.int(At {
                node_type: 1,
                index: None,
                field: "the terminator",
            })?;
            break;
        }
        let node_type = u16::try_from(t).map_err(|_| ErrorKind::UnknownNodeType {
            index: 0,
            node_type: u16::MAX,
        })?;
        let node = r.node(node_type)?;
        by_index.insert(node.index, node);
    }
    Ok(Nodes {
        banner,
        schema,
        user_fields: r.user_fields,
        by_index,
    })
}
