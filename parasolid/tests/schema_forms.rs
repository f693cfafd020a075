//! Transmit files in the forms other Parasolid versions write: the base schema itself
//! (`SCH_<modeller>_13006`, no layout before a type's first node), changes embedded against
//! it (`SCH_<modeller>_<schema>_13006`, `255` before each type's first node), and either with
//! user fields after every node. The file is written here, node by node in the base layouts,
//! for two solids a cam model has: a cylinder (planes, a cylinder, seamless ring edges without
//! vertices) and a cam lobe (a B-surface periodic in u between two planes, bounded by periodic
//! B-curves). Oracle: the cylinder's volume πr²h, the lobe's section area by the shoelace
//! formula over its uniform cubic B-spline evaluated here in closed form; and every form of
//! the file gives the same meshes to the bit, the lobe's periodic B-splines stored with their
//! first vertices repeated or by one period (n vertices, n + 1 knots) alike.

use contact_core::FacetingTolerance;
use parasolid::{Body, ErrorKind, Part, body_mesh, tessellate};
use std::collections::HashSet;
use std::path::Path;

/// One field value as written.
enum F {
    I(i64),
    R(f64),
    C(char),
    V([f64; 3]),
    Unset,
    /// A variable tail of reals.
    Reals(Vec<f64>),
    /// A variable tail of integers.
    Ints(Vec<i64>),
    /// A variable tail of characters.
    Text(String),
    /// A fixed array of characters (logicals).
    Chars(&'static str),
}

use F::{C, I, R, V};

/// How the file is written.
#[derive(Clone, Copy)]
struct Form {
    embedded: bool,
    user_fields: usize,
    /// The lobe's periodic B-splines stored by one period (8 vertices, 9 knots) rather than
    /// with their first three vertices repeated (11 vertices, 15 knots).
    one_period: bool,
}

struct Writer {
    form: Form,
    seen: HashSet<u16>,
    text: String,
}

impl Writer {
    fn new(form: Form) -> Self {
        let key = if form.embedded {
            "SCH_1400068_14000_13006"
        } else {
            "SCH_1300000_13006"
        };
        let banner = ": TRANSMIT FILE created by modeller version 1400068";
        let mut text = format!("T{} {banner}{} {key}", banner.len(), key.len());
        if form.embedded {
            text.push_str("204 ");
        }
        text.push_str(&format!("{} ", form.user_fields));
        Self {
            form,
            seen: HashSet::new(),
            text,
        }
    }

    fn node(&mut self, node_type: u16, index: u32, fields: Vec<F>) {
        let t = &mut self.text;
        t.push_str(&format!("{node_type} "));
        if self.form.embedded && self.seen.insert(node_type) {
            t.push_str("255 ");
        }
        match fields.last() {
            Some(F::Reals(v)) => t.push_str(&format!("{} ", v.len())),
            Some(F::Ints(v)) => t.push_str(&format!("{} ", v.len())),
            Some(F::Text(v)) => t.push_str(&format!("{} ", v.len())),
            _ => {}
        }
        t.push_str(&format!("{index} "));
        for f in fields {
            match f {
                F::I(v) => t.push_str(&format!("{v} ")),
                F::R(v) => t.push_str(&format!("{v:?} ")),
                F::C(c) => t.push(c),
                F::V(v) => v.iter().for_each(|x| t.push_str(&format!("{x:?} "))),
                F::Unset => t.push('?'),
                F::Reals(v) => v.iter().for_each(|x| t.push_str(&format!("{x:?} "))),
                F::Ints(v) => v.iter().for_each(|x| t.push_str(&format!("{x} "))),
                F::Text(v) => t.push_str(&v),
                F::Chars(v) => t.push_str(v),
            }
        }
        for k in 0..self.form.user_fields {
            t.push_str(&format!("{} ", 7 + k));
        }
    }

    /// The whole file: header, then the stream broken into lines of 80 characters anywhere.
    fn finish(mut self) -> Vec<u8> {
        self.text.push_str("1 0 ");
        let key = if self.form.embedded {
            "SCH_1400068_14000_13006"
        } else {
            "SCH_1300000_13006"
        };
        let mut out = format!(
            "**ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz**************************\n\
             **PARASOLID !\"#$%&'()*+,-./:;<=>?@[\\]^_`{{|}}~0123456789**************************\n\
             **PART1;\nFORMAT=text;\nGUISE=transmit;\n**PART2;\nSCH={key};\nUSFLD_SIZE={};\n\
             **PART3;\n**END_OF_HEADER*****************************************************************\n",
            self.form.user_fields
        );
        for line in self.text.as_bytes().chunks(80) {
            out.push_str(std::str::from_utf8(line).unwrap());
            out.push('\n');
        }
        out.into_bytes()
    }
}

/// The fields every geometry node starts with.
fn geom(id: i64, owner: i64, extra: Vec<F>) -> Vec<F> {
    let mut f = vec![I(id), I(0), I(owner), I(0), I(0), I(0), C('+')];
    f.extend(extra);
    f
}

const Z: [f64; 3] = [0.0, 0.0, 1.0];
const X: [f64; 3] = [1.0, 0.0, 0.0];

/// Node indices of one solid: `b` + offset.
struct Solid {
    b: u32,
    next_body: u32,
    /// Its AdamsObjectName.
    element: &'static str,
}

impl Solid {
    fn at(&self, k: u32) -> i64 {
        i64::from(self.b + k)
    }

    /// A solid between z = 0 and z = h: a side face on surface node `b+40`, caps on planes
    /// `b+41` (bottom, normal −z) and `b+42`, ring edges `b+20` (bottom) and `b+21` on curve
    /// nodes `b+50` and `b+51`, running counter-clockwise seen from +z. Geometry nodes are
    /// written by `geometry`.
    fn topology(&self, w: &mut Writer, h: f64) {
        let a = |k| self.at(k);
        let body = self.b;
        w.node(
            12,
            body,
            vec![
                I(a(60)),
                I(a(95)),
                I(0),
                I(0),
                I(0),
                I(0),
                I(0),
                R(1e3),
                R(1e-8),
                I(0),
                I(i64::from(self.next_body)),
                I(0),
                I(1),
                I(0),
                I(1),
                I(0),
                I(0),
                I(0),
                I(0),
                I(0),
                I(a(1)),
                I(0),
                I(0),
            ],
        );
        let b0 = i64::from(body);
        w.node(
            19,
            body + 1,
            vec![I(a(1)), I(0), I(b0), I(a(2)), I(0), I(a(3)), C('S')],
        );
        w.node(
            19,
            body + 2,
            vec![I(a(2)), I(0), I(b0), I(0), I(a(1)), I(0), C('V')],
        );
        w.node(
            13,
            body + 3,
            vec![
                I(a(3)),
                I(0),
                I(b0),
                I(0),
                I(a(10)),
                I(0),
                I(0),
                I(a(1)),
                I(0),
            ],
        );
        // Faces 10 (side), 11 (bottom), 12 (top).
        for (k, surface) in [(10, 40), (11, 41), (12, 42)] {
            let next = if k < 12 { a(k + 1) } else { 0 };
            let prev = if k > 10 { a(k - 1) } else { 0 };
            let first_loop = match k {
                10 => a(30),
                11 => a(32),
                _ => a(33),
            };
            let mut f = vec![
                I(a(k)),
                I(0),
                F::Unset,
                I(next),
                I(prev),
                I(first_loop),
                I(a(3)),
                I(a(surface)),
                C('+'),
            ];
            f.extend((0..5).map(|_| I(0)));
            w.node(14, body + k, f);
        }
        // Loops: 30, 31 on the side (bottom ring, top ring), 32 bottom cap, 33 top cap.
        for (k, fin, face, next) in [
            (30, 70, 10, 31),
            (31, 72, 10, 0),
            (32, 71, 11, 0),
            (33, 73, 12, 0),
        ] {
            let next = if next == 0 { 0 } else { a(next) };
            w.node(
                15,
                body + k,
                vec![I(a(k)), I(0), I(a(fin)), I(a(face)), I(next)],
            );
        }
        // Edges 20 (bottom, on curve 50) and 21 (top, on curve 51); each has its + fin.
        for (k, fin, curve) in [(20, 70, 50), (21, 73, 51)] {
            let mut f = vec![I(a(k)), I(0), F::Unset, I(a(fin)), I(0), I(0), I(a(curve))];
            f.extend((0..3).map(|_| I(0)));
            w.node(16, body + k, f);
        }
        // Fins: 70 side/bottom (+), 71 bottom cap (−), 72 side/top (−), 73 top cap (+).
        for (k, lp, other, edge, sense) in [
            (70, 30, 71, 20, '+'),
            (71, 32, 70, 20, '-'),
            (72, 31, 73, 21, '-'),
            (73, 33, 72, 21, '+'),
        ] {
            w.node(
                17,
                body + k,
                vec![
                    I(0),
                    I(a(lp)),
                    I(a(k)),
                    I(a(k)),
                    I(0),
                    I(a(other)),
                    I(a(edge)),
                    I(0),
                    I(0),
                    C(sense),
                ],
            );
        }
        for (k, z, n) in [(41, 0.0, -1.0), (42, h, 1.0)] {
            let f = geom(
                a(k),
                a(k - 30),
                vec![V([0.0, 0.0, z]), V([0.0, 0.0, n]), V(X)],
            );
            w.node(50, body + k, f);
        }
        // Its name as Adams writes it: attribute AdamsObjectName = `element`.
        w.node(
            81,
            body + 95,
            vec![
                I(a(95)),
                I(a(96)),
                I(b0),
                I(0),
                I(0),
                I(0),
                I(0),
                F::Ints(vec![a(98)]),
            ],
        );
        let mut def = vec![I(0), I(a(97)), I(8001)];
        def.extend((0..8).map(|_| I(0)));
        def.extend([I(0), F::Chars("FFFFTFTFFFFFFF"), F::Ints(vec![3])]);
        w.node(80, body + 96, def);
        w.node(79, body + 97, vec![F::Text("AdamsObjectName".into())]);
        w.node(84, body + 98, vec![F::Text(self.element.into())]);
    }
}

const RADIUS: f64 = 0.02;
const HEIGHT: f64 = 0.01;
const LOBE_HEIGHT: f64 = 0.012;

fn cylinder(w: &mut Writer, s: &Solid) {
    s.topology(w, HEIGHT);
    let a = |k| s.at(k);
    w.node(
        51,
        s.b + 40,
        geom(a(40), a(10), vec![V([0.0; 3]), V(Z), R(RADIUS), V(X)]),
    );
    for (k, z) in [(50, 0.0), (51, HEIGHT)] {
        let f = geom(
            a(k),
            a(k - 30),
            vec![V([0.0, 0.0, z]), V(Z), V(X), R(RADIUS)],
        );
        w.node(31, s.b + k, f);
    }
}

/// The lobe's control polygon (counter-clockwise about z).
fn lobe_polygon() -> Vec<[f64; 2]> {
    let radii = [0.030, 0.026, 0.020, 0.017, 0.016, 0.017, 0.020, 0.026];
    (0..8)
        .map(|k| {
            let t = k as f64 * std::f64::consts::FRAC_PI_4;
            [radii[k] * t.cos(), radii[k] * t.sin()]
        })
        .collect()
}

/// Knots `first`, `first` + 1, … (`n` of them) with multiplicity one: the mult and knot nodes.
fn knots(w: &mut Writer, mult: u32, set: u32, first: usize, n: usize) {
    w.node(127, mult, vec![F::Ints(vec![1; n])]);
    w.node(
        128,
        set,
        vec![F::Reals((first..first + n).map(|k| k as f64).collect())],
    );
}

/// The lobe as a periodic cubic: the polygon with its first three vertices repeated over
/// knots 0 … 14, or stored by one period over knots 3 … 11.
fn lobe(w: &mut Writer, s: &Solid, one_period: bool) {
    s.topology(w, LOBE_HEIGHT);
    let a = |k| s.at(k);
    let poly = lobe_polygon();
    let (n, first, n_knots) = if one_period { (8, 3, 9) } else { (11, 0, 15) };
    // The side: B-surface 40, nurbs 80, vertices 81 (u major, v = 0 then H), knots 82–85.
    w.node(124, s.b + 40, geom(a(40), a(10), vec![I(a(80)), I(0)]));
    w.node(
        126,
        s.b + 80,
        vec![
            C('T'),
            C('F'),
            I(3),
            I(1),
            I(n),
            I(2),
            I(1),
            I(1),
            I(n_knots),
            I(2),
            C('F'),
            C('T'),
            C('F'),
            I(1),
            I(3),
            I(a(81)),
            I(a(82)),
            I(a(84)),
            I(a(83)),
            I(a(85)),
        ],
    );
    let mut vertices = Vec::new();
    for k in 0..n as usize {
        let [x, y] = poly[k % 8];
        vertices.extend([x, y, 0.0, x, y, LOBE_HEIGHT]);
    }
    w.node(45, s.b + 81, vec![F::Reals(vertices)]);
    knots(w, s.b + 82, s.b + 83, first, n_knots as usize);
    w.node(127, s.b + 84, vec![F::Ints(vec![2, 2])]);
    w.node(128, s.b + 85, vec![F::Reals(vec![0.0, 1.0])]);
    // The rings: B-curves 50, 51 with nurbs 86, 87 and vertices 88, 89, sharing knots 82, 83.
    for (k, z) in [(0, 0.0), (1, LOBE_HEIGHT)] {
        w.node(
            134,
            s.b + 50 + k,
            geom(a(50 + k), a(20 + k), vec![I(a(86 + k)), I(0)]),
        );
        w.node(
            136,
            s.b + 86 + k,
            vec![
                I(3),
                I(n),
                I(3),
                I(n_knots),
                I(1),
                C('T'),
                C('T'),
                C('F'),
                I(1),
                I(a(88 + k)),
                I(a(82)),
                I(a(83)),
            ],
        );
        let v = (0..n as usize).flat_map(|i| {
            let [x, y] = poly[i % 8];
            [x, y, z]
        });
        w.node(45, s.b + 88 + k, vec![F::Reals(v.collect())]);
    }
}

fn file(form: Form) -> Vec<u8> {
    stream(form).finish()
}

/// The writer with both solids' nodes, before the terminator and the header.
fn stream(form: Form) -> Writer {
    let mut w = Writer::new(form);
    cylinder(
        &mut w,
        &Solid {
            b: 1,
            next_body: 101,
            element: "PIN",
        },
    );
    lobe(
        &mut w,
        &Solid {
            b: 101,
            next_body: 0,
            element: "LOBE",
        },
        form.one_period,
    );
    w
}

/// The lobe section's area: the uniform cubic B-spline over the closed polygon, each span
/// `(1−t)³P₀ + (3t³−6t²+4)P₁ + (−3t³+3t²+3t+1)P₂ + t³P₃` over 6, sampled 25,000 times per span.
fn lobe_area() -> f64 {
    let p = lobe_polygon();
    let n = 25_000;
    let mut pts = Vec::new();
    for span in 0..8 {
        for i in 0..n {
            let t = i as f64 / n as f64;
            let w = [
                (1.0 - t).powi(3),
                3.0 * t.powi(3) - 6.0 * t * t + 4.0,
                -3.0 * t.powi(3) + 3.0 * t * t + 3.0 * t + 1.0,
                t.powi(3),
            ];
            let mut q = [0.0; 2];
            for (j, wj) in w.iter().enumerate() {
                let c = p[(span + j) % 8];
                q[0] += wj * c[0] / 6.0;
                q[1] += wj * c[1] / 6.0;
            }
            pts.push(q);
        }
    }
    let m = pts.len();
    (0..m)
        .map(|i| {
            let (a, b) = (pts[i], pts[(i + 1) % m]);
            (a[0] * b[1] - b[0] * a[1]) / 2.0
        })
        .sum()
}

/// Meshes of both solids at `ft`, with the chord deviation of each.
fn meshes(bytes: &[u8], ft: f64) -> Vec<(Vec<[f64; 3]>, f64, f64, f64)> {
    let part = Part::from_bytes(Path::new("cam.x_t"), bytes).unwrap_or_else(|e| panic!("{e}"));
    let tol = FacetingTolerance::new(ft).unwrap();
    let names = part.body_names().unwrap();
    assert_eq!(names.len(), 2);
    names
        .iter()
        .map(|n| {
            let body = Body::read(&part, n.index).unwrap_or_else(|e| panic!("{e}"));
            let mesh = body_mesh(&part, &body, tol, "solid").unwrap_or_else(|e| panic!("{e}"));
            let t = tessellate(&part, &body, tol).unwrap();
            let area: f64 = (0..mesh.triangles().len())
                .map(|i| mesh.triangle_area(i))
                .sum();
            let points = (0..mesh.triangles().len())
                .flat_map(|i| mesh.triangle(i).map(|p| [p.x, p.y, p.z]))
                .collect();
            (points, t.signed_volume(), t.deviation * area, t.deviation)
        })
        .collect()
}

#[test]
fn a_base_schema_file_reads_and_its_solids_close_on_their_volumes() {
    let bytes = file(Form {
        embedded: false,
        user_fields: 0,
        one_period: false,
    });
    let exact = [
        std::f64::consts::PI * RADIUS * RADIUS * HEIGHT,
        lobe_area() * LOBE_HEIGHT,
    ];
    let mut errors = [[0.0; 2]; 2];
    for (k, ft) in [300.0028, 3000.0].into_iter().enumerate() {
        for (s, (_, volume, bound, _)) in meshes(&bytes, ft).into_iter().enumerate() {
            errors[s][k] = (volume - exact[s]).abs();
            assert!(
                errors[s][k] < bound,
                "solid {s} FT {ft}: volume {volume:e} against {:e}, bound {bound:e}",
                exact[s]
            );
        }
    }
    for e in errors {
        assert!(e[1] < e[0] / 3.0, "volume errors {e:?} do not fall");
    }
}

#[test]
fn embedded_user_field_and_one_period_forms_give_the_same_meshes() {
    let reference = meshes(
        &file(Form {
            embedded: false,
            user_fields: 0,
            one_period: false,
        }),
        300.0028,
    );
    for (embedded, user_fields, one_period) in [
        (true, 0, false),
        (false, 2, false),
        (true, 1, false),
        (false, 0, true),
    ] {
        let other = meshes(
            &file(Form {
                embedded,
                user_fields,
                one_period,
            }),
            300.0028,
        );
        for (a, b) in reference.iter().zip(&other) {
            assert_eq!(
                a.0, b.0,
                "embedded {embedded}, user fields {user_fields}, one period {one_period}"
            );
        }
    }
}

#[test]
fn other_schemas_are_refused_by_their_key() {
    let form = Form {
        embedded: false,
        user_fields: 0,
        one_period: false,
    };
    let edited = |from: &str, to: &str| {
        let mut w = stream(form);
        let text = w.text.replacen(from, to, 1);
        assert_ne!(text, w.text, "{from} is in the stream");
        w.text = text;
        w.finish()
    };
    for (to, says) in [
        ("SCH_1200000_12006", "schema 12006"),
        ("SCH_1300000_13007", "schema 13007"),
        ("SCH_1400068_14000_12006", "base schema 12006"),
    ] {
        let bad = edited("17 SCH_1300000_13006", &format!("{} {to}", to.len()));
        let e = Part::from_bytes(Path::new("old.x_t"), &bad).unwrap_err();
        assert!(
            matches!(&e.kind, ErrorKind::UnsupportedSchema { key, .. } if key == to),
            "{e}"
        );
        let msg = e.to_string();
        assert!(msg.starts_with("old.x_t: ") && msg.contains(says), "{msg}");
    }
    // A user field size that is not the one written misaligns the stream: an error, no panic.
    let bad = edited("_130060 12 1 ", "_130061 12 1 ");
    assert!(Part::from_bytes(Path::new("u.x_t"), &bad).is_err());
}

#[test]
fn the_written_cylinder_is_recognised_as_one_and_the_lobe_is_not() {
    let bytes = file(Form {
        embedded: false,
        user_fields: 0,
        one_period: false,
    });
    let part = Part::from_bytes(Path::new("cam.x_t"), &bytes).unwrap();
    let shapes: Vec<_> = part
        .body_names()
        .unwrap()
        .iter()
        .map(|n| {
            parasolid::primitive::recognise(&Body::read(&part, n.index).unwrap()).map(|p| p.shape)
        })
        .collect();
    assert_eq!(
        shapes,
        [
            Some(parasolid::Shape::Frustum {
                bottom: RADIUS,
                top: RADIUS,
                length: HEIGHT
            }),
            None
        ]
    );
}

/// The fixture `tests/data/parasolid/cam_and_pin.x_t` (read by the run tests of the workspace)
/// is this file's base-schema form; `CONTACT_WRITE_FIXTURES=1` rewrites it.
#[test]
fn the_fixture_is_the_base_schema_form_of_this_file() {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/data/parasolid/cam_and_pin.x_t");
    let bytes = file(Form {
        embedded: false,
        user_fields: 0,
        one_period: false,
    });
    if std::env::var_os("CONTACT_WRITE_FIXTURES").is_some() {
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(&path, &bytes).unwrap();
    }
    let fixture = std::fs::read(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    assert!(
        fixture == bytes,
        "{} is not this file's output",
        path.display()
    );
    let part = Part::from_bytes(&path, &fixture).unwrap();
    let names: Vec<_> = part
        .body_names()
        .unwrap()
        .into_iter()
        .map(|n| n.element.unwrap())
        .collect();
    assert_eq!(names, ["PIN", "LOBE"]);
}
