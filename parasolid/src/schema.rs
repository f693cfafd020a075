//! Node layouts: the base schema `SCH_13006` that files describe their own layouts against
//! (XT Format Reference §2.1.2), and the changes a file embeds.
//!
//! The base layouts are the reference's node structures (chapter "Schema definitions") with
//! only the transmitted fields, in transmit order. A file that writes a type in the base layout
//! gives `255` at the type's first node; otherwise it gives the new field count and a list of
//! edits against the base layout: `C` copy the next base field, `D` delete it, `I` insert a
//! described field, `A` append one, `Z` end. A type the base does not have is described whole:
//! name, description and every field. A described field is its name, its pointer class (0 for
//! data), its element count (0 one value, 1 a variable-length tail followed by a logical, more a
//! fixed array) and, for data, its type letter.
//!
//! A file of the base schema itself (key `SCH_<modeller>_13006`) writes every node in these
//! layouts with no layout before a type's first node ([`Form`]).
//!
//! LIST's fifth and eighth base fields are taken as `list_type` (u) and `notransmit` (l): the
//! writers that embed changes delete exactly those two fields and insert two of these names and
//! kinds at the front.

/// How a field's values are written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// `d u n w t`: integers.
    Int,
    /// `p`: a pointer (a node index, 0 for none).
    Pointer,
    /// `f`: a real.
    Real,
    /// `c l`: one character (logicals are `T`/`F`).
    Char,
    /// `v h`: three reals (an `h` vector is written by its position).
    Vector,
    /// `i`: two reals.
    Interval,
    /// `b`: six reals.
    Box,
}

impl Kind {
    /// The kind of a type letter.
    pub fn from_letter(letter: &str) -> Option<Self> {
        Some(match letter {
            "d" | "u" | "n" | "w" | "t" => Self::Int,
            "p" => Self::Pointer,
            "f" => Self::Real,
            "c" | "l" => Self::Char,
            "v" | "h" => Self::Vector,
            "i" => Self::Interval,
            "b" => Self::Box,
            _ => return None,
        })
    }
}

/// How many values a field holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Count {
    /// One value.
    One,
    /// A fixed number of values.
    Fixed(usize),
    /// The node's variable-length tail: as many as the count written before the node's index.
    Variable,
}

/// One field of a layout.
#[derive(Debug, Clone, PartialEq)]
pub struct Field {
    /// Its name (the reference's).
    pub name: String,
    /// How its values are written.
    pub kind: Kind,
    /// How many.
    pub count: Count,
}

/// The layout of one node type as a file writes it.
#[derive(Debug, Clone, PartialEq)]
pub struct Layout {
    /// The fields in transmit order.
    pub fields: Vec<Field>,
}

impl Layout {
    /// Whether the last field is a variable-length tail (its count precedes the node index).
    pub fn is_variable(&self) -> bool {
        self.fields
            .last()
            .is_some_and(|f| f.count == Count::Variable)
    }

    /// The position of field `name`.
    pub fn position(&self, name: &str) -> Option<usize> {
        self.fields.iter().position(|f| f.name == name)
    }
}

/// The base schema's number: embedded changes are written against it.
pub const BASE_SCHEMA: &str = "13006";

/// How a file lays out its nodes, from its schema key `SCH_<modeller>_<schema>[_<base>]`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Form {
    /// `SCH_<modeller>_13006`: the base schema itself; nodes carry no layout, and the key is
    /// followed by one integer (the user field size).
    Base,
    /// `SCH_<modeller>_<schema>_13006`: each type's first node is preceded by its layout (`255`
    /// for the base one, else its changes), and the key is followed by two integers (the
    /// highest node type, then the user field size).
    Embedded,
}

impl Form {
    /// The form of schema key `key`; keys of other schemas are refused by name.
    pub fn of(key: &str) -> Result<Self, crate::error::ErrorKind> {
        let refuse = |why: &str| crate::error::ErrorKind::UnsupportedSchema {
            key: key.to_string(),
            why: why.to_string(),
        };
        let parts: Vec<&str> = key.split('_').collect();
        let numeric = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
        if parts[0] != "SCH" || parts.len() < 3 || !parts[1..].iter().all(|p| numeric(p)) {
            return Err(refuse(
                "not a schema key (SCH_<modeller>_<schema>[_<base>])",
            ));
        }
        match parts[2..] {
            [BASE_SCHEMA] => Ok(Self::Base),
            [_, BASE_SCHEMA] => Ok(Self::Embedded),
            [schema] => Err(refuse(&format!(
                "schema {schema} is written without embedded changes and its layouts are not known"
            ))),
            [_, base] => Err(refuse(&format!(
                "its changes are embedded against base schema {base}, not 13006"
            ))),
            _ => Err(refuse(
                "not a schema key (SCH_<modeller>_<schema>[_<base>])",
            )),
        }
    }
}

/// Node type numbers the reader uses.
pub mod types {
    /// Body.
    pub const BODY: u16 = 12;
    /// Shell.
    pub const SHELL: u16 = 13;
    /// Face.
    pub const FACE: u16 = 14;
    /// Loop.
    pub const LOOP: u16 = 15;
    /// Edge.
    pub const EDGE: u16 = 16;
    /// Fin (half-edge).
    pub const FIN: u16 = 17;
    /// Vertex.
    pub const VERTEX: u16 = 18;
    /// Region.
    pub const REGION: u16 = 19;
    /// Point.
    pub const POINT: u16 = 29;
    /// Line.
    pub const LINE: u16 = 30;
    /// Circle.
    pub const CIRCLE: u16 = 31;
    /// Ellipse.
    pub const ELLIPSE: u16 = 32;
    /// Intersection curve.
    pub const INTERSECTION: u16 = 38;
    /// Chart (an intersection curve's stored points).
    pub const CHART: u16 = 40;
    /// Limit (an intersection curve's end).
    pub const LIMIT: u16 = 41;
    /// B-spline vertices.
    pub const BSPLINE_VERTICES: u16 = 45;
    /// Plane.
    pub const PLANE: u16 = 50;
    /// Cylinder.
    pub const CYLINDER: u16 = 51;
    /// Cone.
    pub const CONE: u16 = 52;
    /// Sphere.
    pub const SPHERE: u16 = 53;
    /// Torus.
    pub const TORUS: u16 = 54;
    /// Swept surface.
    pub const SWEPT_SURF: u16 = 67;
    /// Spun surface.
    pub const SPUN_SURF: u16 = 68;
    /// Attribute definition.
    pub const ATTRIB_DEF: u16 = 80;
    /// Attribute.
    pub const ATTRIBUTE: u16 = 81;
    /// Attribute definition name.
    pub const ATT_DEF_ID: u16 = 79;
    /// Character values.
    pub const CHAR_VALUES: u16 = 84;
    /// B-surface.
    pub const B_SURFACE: u16 = 124;
    /// NURBS surface data.
    pub const NURBS_SURF: u16 = 126;
    /// Knot multiplicities.
    pub const KNOT_MULT: u16 = 127;
    /// Knots.
    pub const KNOT_SET: u16 = 128;
    /// Trimmed curve.
    pub const TRIMMED_CURVE: u16 = 133;
    /// B-curve.
    pub const B_CURVE: u16 = 134;
    /// NURBS curve data.
    pub const NURBS_CURVE: u16 = 136;
    /// Surface parameter-space curve.
    pub const SP_CURVE: u16 = 137;
    /// Part list (root of a part file).
    pub const PART_XMT_BLOCK: u16 = 176;
}

/// The name of a node type, where the reader knows it.
pub fn type_name(node_type: u16) -> Option<&'static str> {
    BASE.iter()
        .find(|(t, _, _)| *t == node_type)
        .map(|(_, n, _)| *n)
        .or(match node_type {
            176 => Some("PART_XMT_BLOCK"),
            204 => Some("INTERSECTION_DATA"),
            _ => None,
        })
}

const GEOM: &str =
    "node_id:d attributes_features:p owner:p next:p previous:p geometric_owner:p sense:c";

/// Base layouts: type, name, fields as `name:letter` (a count after the letter for a fixed
/// array, `*` for the variable tail).
const BASE: &[(u16, &str, &str)] = &[
    (
        12,
        "BODY",
        "highest_node_id:d attributes_features:p attribute_chains:p surface:p curve:p point:p key:p res_size:f res_linear:f ref_instance:p next:p previous:p state:u owner:p body_type:u nom_geom_state:u shell:p boundary_surface:p boundary_curve:p boundary_point:p region:p edge:p vertex:p",
    ),
    (
        13,
        "SHELL",
        "node_id:d attributes_features:p body:p next:p face:p edge:p vertex:p region:p front_face:p",
    ),
    (
        14,
        "FACE",
        "node_id:d attributes_features:p tolerance:f next:p previous:p loop:p shell:p surface:p sense:c next_on_surface:p previous_on_surface:p next_front:p previous_front:p front_shell:p",
    ),
    (
        15,
        "LOOP",
        "node_id:d attributes_features:p fin:p face:p next:p",
    ),
    (
        16,
        "EDGE",
        "node_id:d attributes_features:p tolerance:f fin:p previous:p next:p curve:p next_on_curve:p previous_on_curve:p owner:p",
    ),
    (
        17,
        "FIN",
        "attributes_features:p loop:p forward:p backward:p vertex:p other:p edge:p curve:p next_at_vx:p sense:c",
    ),
    (
        18,
        "VERTEX",
        "node_id:d attributes_features:p fin:p previous:p next:p point:p tolerance:f owner:p",
    ),
    (
        19,
        "REGION",
        "node_id:d attributes_features:p body:p next:p previous:p shell:p type:c",
    ),
    (
        29,
        "POINT",
        "node_id:d attributes_features:p owner:p next:p previous:p pvec:v",
    ),
    (30, "LINE", "@ pvec:v direction:v"),
    (31, "CIRCLE", "@ centre:v normal:v x_axis:v radius:f"),
    (
        32,
        "ELLIPSE",
        "@ centre:v normal:v x_axis:v major_radius:f minor_radius:f",
    ),
    (38, "INTERSECTION", "@ surface:p2 chart:p start:p end:p"),
    (
        40,
        "CHART",
        "base_parameter:f base_scale:f chart_count:d chordal_error:f angular_error:f parameter_error:f2 hvec:h*",
    ),
    (41, "LIMIT", "type:c hvec:h*"),
    (45, "BSPLINE_VERTICES", "vertices:f*"),
    (46, "OFFSET_CURVE", "@ surface:p curve:p offset:f"),
    (50, "PLANE", "@ pvec:v normal:v x_axis:v"),
    (51, "CYLINDER", "@ pvec:v axis:v radius:f x_axis:v"),
    (
        52,
        "CONE",
        "@ pvec:v axis:v radius:f sin_half_angle:f cos_half_angle:f x_axis:v",
    ),
    (53, "SPHERE", "@ centre:v radius:f axis:v x_axis:v"),
    (
        54,
        "TORUS",
        "@ centre:v axis:v major_radius:f minor_radius:f x_axis:v",
    ),
    (
        56,
        "BLENDED_EDGE",
        "@ blend_type:c surface:p2 spine:p range:f2 thumb_weight:f2 boundary:p2 start:p end:p",
    ),
    (59, "BLEND_BOUND", "@ boundary:n blend:p"),
    (
        60,
        "OFFSET_SURF",
        "@ check:c true_offset:l surface:p offset:f scale:f",
    ),
    (67, "SWEPT_SURF", "@ section:p sweep:v scale:f"),
    (
        68,
        "SPUN_SURF",
        "@ profile:p base:v axis:v start:h end:h start_param:f end_param:f x_axis:v scale:f",
    ),
    (
        70,
        "LIST",
        "node_id:d owner:p next:p previous:p list_type:u list_length:d block_length:d notransmit:l list_block:p",
    ),
    (71, "REAL_LIS_BLOCK", "n_entries:d next_block:p entries:f*"),
    (
        72,
        "INTEGER_LIS_BLOCK",
        "n_entries:d next_block:p entries:d*",
    ),
    (73, "TAG_LIS_BLOCK", "n_entries:d next_block:p entries:t*"),
    (
        74,
        "POINTER_LIS_BLOCK",
        "n_entries:d next_block:p entries:p*",
    ),
    (79, "ATT_DEF_ID", "string:c*"),
    (
        80,
        "ATTRIB_DEF",
        "next:p identifier:p type_id:d actions:u8 field_names:p legal_owners:l14 fields:u*",
    ),
    (
        81,
        "ATTRIBUTE",
        "node_id:d definition:p owner:p next:p previous:p next_of_type:p previous_of_type:p fields:p*",
    ),
    (82, "INT_VALUES", "values:d*"),
    (83, "REAL_VALUES", "values:f*"),
    (84, "CHAR_VALUES", "values:c*"),
    (85, "POINT_VALUES", "values:v*"),
    (86, "VECTOR_VALUES", "values:v*"),
    (87, "AXIS_VALUES", "values:v*"),
    (88, "TAG_VALUES", "values:t*"),
    (89, "DIRECTION_VALUES", "values:v*"),
    (
        90,
        "FEATURE",
        "node_id:d attributes_features:p owner:p next:p previous:p type:u first_member:p",
    ),
    (
        91,
        "MEMBER_OF_FEATURE",
        "dummy_node_id:d owning_feature:p owner:p next:p previous:p next_member:p previous_member:p",
    ),
    (96, "SHORT_VALUES", "values:n*"),
    (97, "BOX_VALUES", "values:b*"),
    (98, "UNICODE_VALUES", "values:w*"),
    (99, "FIELD_NAMES", "names:p*"),
    (
        100,
        "TRANSFORM",
        "node_id:d owner:p next:p previous:p rotation_matrix:f9 translation_vector:v scale:f flag:d perspective_vector:v",
    ),
    (
        101,
        "WORLD",
        "assembly:p attribute:p body:p transform:p surface:p curve:p point:p alive:l attrib_def:p highest_id:d current_id:d",
    ),
    (102, "KEY", "string:c*"),
    (124, "B_SURFACE", "@ nurbs:p data:p"),
    (
        125,
        "SURFACE_DATA",
        "original_uint:i original_vint:i extended_uint:i extended_vint:i self_int:u original_u_start:c original_u_end:c original_v_start:c original_v_end:c extended_u_start:c extended_u_end:c extended_v_start:c extended_v_end:c analytic_form_type:c swept_form_type:c spun_form_type:c blend_form_type:c analytic_form:p swept_form:p spun_form:p blend_form:p",
    ),
    (
        126,
        "NURBS_SURF",
        "u_periodic:l v_periodic:l u_degree:n v_degree:n n_u_vertices:d n_v_vertices:d u_knot_type:u v_knot_type:u n_u_knots:d n_v_knots:d rational:l u_closed:l v_closed:l surface_form:u vertex_dim:n bspline_vertices:p u_knot_mult:p v_knot_mult:p u_knots:p v_knots:p",
    ),
    (127, "KNOT_MULT", "mult:n*"),
    (128, "KNOT_SET", "knots:f*"),
    (132, "PCURVE", "@ bsp_parms:l surface:p bspline:p"),
    (
        133,
        "TRIMMED_CURVE",
        "@ basis_curve:p point_1:v point_2:v parm_1:f parm_2:f",
    ),
    (134, "B_CURVE", "@ nurbs:p data:p"),
    (135, "CURVE_DATA", "self_int:u analytic_form:p"),
    (
        136,
        "NURBS_CURVE",
        "degree:n n_vertices:d vertex_dim:n n_knots:d knot_type:u periodic:l closed:l rational:l curve_form:u bspline_vertices:p knot_mult:p knots:p",
    ),
    (
        137,
        "SP_CURVE",
        "@ surface:p b_curve:p original:p tolerance_to_original:f",
    ),
    (
        141,
        "GEOMETRIC_OWNER",
        "owner:p next:p previous:p shared_geometry:p",
    ),
];

fn parse_fields(spec: &str) -> Vec<Field> {
    let spec = spec.replacen('@', GEOM, 1);
    spec.split_whitespace()
        .map(|tok| {
            let (name, rest) = tok.split_once(':').expect("base table entry name:kind");
            let (letter, count) = rest.split_at(1);
            let kind = Kind::from_letter(letter).expect("base table letter");
            let count = match count {
                "" => Count::One,
                "*" => Count::Variable,
                n => Count::Fixed(n.parse().expect("base table count")),
            };
            Field {
                name: name.to_string(),
                kind,
                count,
            }
        })
        .collect()
}

/// The base layout of a node type, if the base schema has it.
pub fn base_layout(node_type: u16) -> Option<Layout> {
    BASE.iter()
        .find(|(t, _, _)| *t == node_type)
        .map(|(_, _, spec)| Layout {
            fields: parse_fields(spec),
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_base_entry_parses_and_names_are_unique() {
        for (t, name, _) in BASE {
            let l = base_layout(*t).unwrap();
            let mut names: Vec<_> = l.fields.iter().map(|f| f.name.as_str()).collect();
            names.sort_unstable();
            names.dedup();
            assert_eq!(names.len(), l.fields.len(), "{name}");
            // Only the last field may be the variable tail.
            for f in &l.fields[..l.fields.len() - 1] {
                assert_ne!(f.count, Count::Variable, "{name}");
            }
        }
        assert_eq!(base_layout(types::CYLINDER).unwrap().fields.len(), 11);
        assert_eq!(base_layout(types::BODY).unwrap().fields.len(), 23);
        assert_eq!(type_name(types::TORUS), Some("TORUS"));
    }
}
