//! A read transmit file: nodes by index, with checked access to typed fields, and its bodies
//! with their Adams names.

use crate::error::{Error, ErrorKind};
use crate::schema::types;
use crate::stream::{Node, Nodes, Value};
use crate::text::Stream;
use std::path::{Path, PathBuf};

/// A Parasolid text transmit file, read.
#[derive(Debug, Clone)]
pub struct Part {
    /// The file it was read from (for messages).
    pub file: PathBuf,
    nodes: Nodes,
}

/// A body of the part and the names Adams gave it.
#[derive(Debug, Clone, PartialEq)]
pub struct BodyName {
    /// The BODY node's index.
    pub index: u32,
    /// Attribute `AdamsPartName` (the PART's name), if set.
    pub part: Option<String>,
    /// Attribute `AdamsObjectName` (the GRAPHICS' ELEMENT), if set.
    pub element: Option<String>,
    /// Attribute `UG2/ADAMS_ID`: the Adams id of the PART the body belongs to, if set.
    pub adams_id: Option<i64>,
    /// Attribute `SDL/TYSA_DENSITY` in kg/m³, if set.
    pub density: Option<f64>,
}

impl Part {
    /// Reads a text transmit file.
    pub fn read(path: &Path) -> Result<Self, Error> {
        let bytes =
            std::fs::read(path).map_err(|e| Error::new(path, ErrorKind::Io(e.to_string())))?;
        Self::from_bytes(path, &bytes)
    }

    /// Reads a transmit file's text; `file` names it in messages.
    pub fn from_bytes(file: &Path, bytes: &[u8]) -> Result<Self, Error> {
        let wrap = |kind| Error::new(file, kind);
        let stream = Stream::new(bytes).map_err(wrap)?;
        let nodes = crate::stream::read(&stream).map_err(wrap)?;
        Ok(Self {
            file: file.to_path_buf(),
            nodes,
        })
    }

    /// The schema key the file names.
    pub fn schema(&self) -> &str {
        &self.nodes.schema
    }

    /// Number of nodes read.
    pub fn node_count(&self) -> usize {
        self.nodes.by_index.len()
    }

    /// An error in this file.
    pub fn error(&self, kind: ErrorKind) -> Error {
        Error::new(&self.file, kind)
    }

    /// The node at `index`; `from`/`field` name the reference for a dangling one.
    pub fn node(&self, index: u32, from: &Node, field: &'static str) -> Result<&Node, Error> {
        self.nodes.by_index.get(&index).ok_or_else(|| {
            self.error(ErrorKind::DanglingReference {
                node: from.reference(),
                field,
                target: index,
                why: "which is not in the file".into(),
            })
        })
    }

    /// The node at `index`, which must be of one of `allowed` types.
    pub fn node_of(
        &self,
        index: u32,
        from: &Node,
        field: &'static str,
        allowed: &[u16],
    ) -> Result<&Node, Error> {
        let n = self.node(index, from, field)?;
        if !allowed.contains(&n.node_type) {
            return Err(self.error(ErrorKind::DanglingReference {
                node: from.reference(),
                field,
                target: index,
                why: format!(
                    "which is a {} node, not the kind expected",
                    crate::schema::type_name(n.node_type).unwrap_or("unknown")
                ),
            }));
        }
        Ok(n)
    }

    fn field<'n>(&self, node: &'n Node, field: &'static str) -> Result<&'n Value, Error> {
        node.get(field).ok_or_else(|| {
            self.error(ErrorKind::MissingField {
                node: node.reference(),
                field,
                why: "is not in this file's layout",
            })
        })
    }

    fn unset(&self, node: &Node, field: &'static str) -> Error {
        self.error(ErrorKind::MissingField {
            node: node.reference(),
            field,
            why: "is unset or not of the expected kind",
        })
    }

    /// A pointer field: `None` for a null (0) pointer.
    pub fn ptr(&self, node: &Node, field: &'static str) -> Result<Option<u32>, Error> {
        match self.field(node, field)? {
            Value::Int(0) | Value::Unset => Ok(None),
            Value::Int(v) => u32::try_from(*v)
                .map(Some)
                .map_err(|_| self.unset(node, field)),
            _ => Err(self.unset(node, field)),
        }
    }

    /// A pointer field that must be set, and the node it points to (of one of `allowed`).
    pub fn follow(
        &self,
        node: &Node,
        field: &'static str,
        allowed: &[u16],
    ) -> Result<&Node, Error> {
        let i = self
            .ptr(node, field)?
            .ok_or_else(|| self.unset(node, field))?;
        self.node_of(i, node, field, allowed)
    }

    /// An integer field.
    pub fn int(&self, node: &Node, field: &'static str) -> Result<i64, Error> {
        match self.field(node, field)? {
            Value::Int(v) => Ok(*v),
            _ => Err(self.unset(node, field)),
        }
    }

    /// A real field that must be set.
    pub fn real(&self, node: &Node, field: &'static str) -> Result<f64, Error> {
        match self.field(node, field)? {
            Value::Real(v) if v.is_finite() => Ok(*v),
            _ => Err(self.unset(node, field)),
        }
    }

    /// A vector field that must be set.
    pub fn vector(&self, node: &Node, field: &'static str) -> Result<[f64; 3], Error> {
        match self.field(node, field)? {
            Value::Vector(v) => Ok(*v),
            _ => Err(self.unset(node, field)),
        }
    }

    /// A character or logical field.
    pub fn char(&self, node: &Node, field: &'static str) -> Result<u8, Error> {
        match self.field(node, field)? {
            Value::Char(c) => Ok(*c),
            _ => Err(self.unset(node, field)),
        }
    }

    /// A real-array field (fixed or variable).
    pub fn reals<'n>(&self, node: &'n Node, field: &'static str) -> Result<&'n [f64], Error> {
        match self.field(node, field)? {
            Value::Reals(v) => Ok(v),
            _ => Err(self.unset(node, field)),
        }
    }

    /// An integer- or pointer-array field.
    pub fn ints<'n>(&self, node: &'n Node, field: &'static str) -> Result<&'n [i64], Error> {
        match self.field(node, field)? {
            Value::Ints(v) => Ok(v),
            _ => Err(self.unset(node, field)),
        }
    }

    /// A vector-array field.
    pub fn vectors<'n>(
        &self,
        node: &'n Node,
        field: &'static str,
    ) -> Result<&'n [[f64; 3]], Error> {
        match self.field(node, field)? {
            Value::Vectors(v) => Ok(v),
            _ => Err(self.unset(node, field)),
        }
    }

    /// The BODY nodes the root lists (a part list, a single body, or every BODY node).
    pub fn body_indices(&self) -> Result<Vec<u32>, Error> {
        let root = self.nodes.by_index.get(&1);
        let mut out = Vec::new();
        match root {
            Some(r) if r.node_type == types::PART_XMT_BLOCK || r.node_type == 74 => {
                for &e in self.ints(r, "entries")? {
                    let i = u32::try_from(e).map_err(|_| self.unset(r, "entries"))?;
                    if i == 0 {
                        continue;
                    }
                    if self.node(i, r, "entries")?.node_type == types::BODY {
                        out.push(i);
                    }
                }
            }
            _ => {
                out = self
                    .nodes
                    .by_index
                    .values()
                    .filter(|n| n.node_type == types::BODY)
                    .map(|n| n.index)
                    .collect();
                out.sort_unstable();
            }
        }
        Ok(out)
    }

    /// Every body and its Adams names.
    pub fn body_names(&self) -> Result<Vec<BodyName>, Error> {
        self.body_indices()?
            .into_iter()
            .map(|i| self.body_name(i))
            .collect()
    }

    /// The Adams names of the body at `index`, from its attributes.
    pub fn body_name(&self, index: u32) -> Result<BodyName, Error> {
        let body = self.nodes.by_index.get(&index).ok_or_else(|| {
            self.error(ErrorKind::BodyNotFound {
                part: String::new(),
                element: format!("node {index}"),
                known: String::new(),
            })
        })?;
        let mut name = BodyName {
            index,
            part: None,
            element: None,
            adams_id: None,
            density: None,
        };
        let mut next = self.ptr(body, "attributes_features")?;
        let mut from = body;
        let mut guard = 0;
        while let Some(i) = next {
            guard += 1;
            if guard > 100_000 {
                return Err(self.error(ErrorKind::Geometry {
                    node: body.reference(),
                    what: "its attribute chain does not end".into(),
                }));
            }
            let a = self.node(i, from, "next")?;
            if a.node_type == types::ATTRIBUTE {
                let def = self.follow(a, "definition", &[types::ATTRIB_DEF])?;
                let id = self.follow(def, "identifier", &[types::ATT_DEF_ID])?;
                let key = match id.get("string") {
                    Some(Value::Text(s)) => s.as_str(),
                    _ => "",
                };
                let first = self
                    .ints(a, "fields")?
                    .iter()
                    .copied()
                    .find(|&f| f > 0)
                    .unwrap_or(0);
                let value = if first > 0 {
                    self.nodes.by_index.get(&(first as u32))
                } else {
                    None
                };
                match (key, value.and_then(|v| v.get("values"))) {
                    ("AdamsPartName", Some(Value::Text(s))) => name.part = Some(s.clone()),
                    ("AdamsObjectName", Some(Value::Text(s))) => name.element = Some(s.clone()),
                    ("SDL/TYSA_DENSITY", Some(Value::Reals(r))) => {
                        name.density = r.first().copied()
                    }
                    ("UG2/ADAMS_ID", Some(Value::Ints(r))) => name.adams_id = r.first().copied(),
                    _ => {}
                }
            }
            from = a;
            next = self.ptr(a, "next")?;
        }
        Ok(name)
    }

    /// The body Adams names `element` on part `part` (`GRAPHICS …, EXTERNAL, RM = marker on
    /// part, ELEMENT = element`): the one whose AdamsPartName and AdamsObjectName match
    /// (ASCII case-insensitively, as Adams names are).
    pub fn find_body(&self, part: &str, element: &str) -> Result<u32, Error> {
        let names = self.body_names()?;
        let same =
            |a: &Option<String>, b: &str| a.as_deref().is_some_and(|a| a.eq_ignore_ascii_case(b));
        names
            .iter()
            .find(|n| same(&n.part, part) && same(&n.element, element))
            .map(|n| n.index)
            .ok_or_else(|| {
                let known = names
                    .iter()
                    .map(|n| {
                        format!(
                            "{}/{}",
                            n.part.as_deref().unwrap_or("?"),
                            n.element.as_deref().unwrap_or("?")
                        )
                    })
                    .collect::<Vec<_>>()
                    .join(", ");
                self.error(ErrorKind::BodyNotFound {
                    part: part.into(),
                    element: element.into(),
                    known,
                })
            })
    }

    /// The body Adams names `element` on the PART with Adams id `part_id` (and name
    /// `part_name` where the caller knows it): among the bodies whose AdamsObjectName is
    /// `element` (names repeat across parts), the one whose `UG2/ADAMS_ID` is the part's id or
    /// whose AdamsPartName is its name. Where the bodies carry no `UG2/ADAMS_ID` and the
    /// caller knows no part name, the one body whose AdamsObjectName is `element`, if only
    /// one is.
    pub fn find_body_on_part(
        &self,
        part_id: u32,
        part_name: Option<&str>,
        element: &str,
    ) -> Result<u32, Error> {
        let names = self.body_names()?;
        let named: Vec<&BodyName> = names
            .iter()
            .filter(|n| {
                n.element
                    .as_deref()
                    .is_some_and(|e| e.eq_ignore_ascii_case(element))
            })
            .collect();
        let on_part = named.iter().find(|n| {
            n.adams_id == Some(i64::from(part_id))
                || part_name
                    .is_some_and(|p| n.part.as_deref().is_some_and(|q| q.eq_ignore_ascii_case(p)))
        });
        // A file without the part's id or name on its bodies: an ELEMENT only one body
        // carries is that body.
        let alone = match named.as_slice() {
            [only] if only.adams_id.is_none() && part_name.is_none() => Some(only),
            _ => None,
        };
        let found = on_part.or(alone);
        found.map(|n| n.index).ok_or_else(|| {
            let known = names
                .iter()
                .map(|n| {
                    format!(
                        "{} (PART/{})/{}",
                        n.part.as_deref().unwrap_or("?"),
                        n.adams_id.map_or("?".to_string(), |i| i.to_string()),
                        n.element.as_deref().unwrap_or("?")
                    )
                })
                .collect::<Vec<_>>()
                .join(", ");
            self.error(ErrorKind::BodyNotFound {
                part: format!("PART/{part_id}"),
                element: element.into(),
                known,
            })
        })
    }

    /// A part with no nodes, for tests that build bodies directly.
    #[cfg(test)]
    pub(crate) fn empty(file: &Path) -> Self {
        Self {
            file: file.to_path_buf(),
            nodes: Nodes {
                banner: String::new(),
                schema: String::new(),
                user_fields: 0,
                by_index: Default::default(),
            },
        }
    }

    /// The node at `index` (no reference check), for readers of this crate.
    pub(crate) fn get(&self, index: u32) -> Option<&Node> {
        self.nodes.by_index.get(&index)
    }
}
