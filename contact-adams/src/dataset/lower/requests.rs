//! REQUEST statements (kept for output) and GCON statements (the distance form).
//!
//! A REQUEST is checked as Adams checks it before a run: its markers exist, its functions
//! parse, every element it reads exists and has the component asked for (`SFORCE(1,0,2,0)` of
//! a ROTATIONAL SFORCE is refused, as Adams refuses it: "Wrong component: 2. No force in
//! corresponding object."), and `ORIENT` asks for a type this reader evaluates (27, Euler
//! parameters). An unsupported function inside is a warning: the request's other columns
//! still work, and that column is written as 0.

use super::Lowering;
use super::elements::marker;
use super::reader::{Problem, Reader};
use crate::dataset::parser::{ExprText, Statement};
use crate::expr::{ElementKind, Expr, ExprErrorKind, Measure, parse_expr};
use crate::model::{Freedom, Gcon, Model, Request};

/// The REQUEST function arguments, in the order they are read.
const FUNCTIONS: [&str; 9] = ["F1", "F2", "F3", "F4", "F5", "F6", "F7", "F8", "FUNCTION"];

/// REQUEST statements, kept for output.
pub(crate) fn lower_requests(low: &mut Lowering, model: &mut Model, requests: &[&Statement]) {
    for st in requests {
        let Some((id, _)) = st.id else { continue };
        let r = Reader::new(st);
        let result = (|| -> Result<Request, Problem> {
            let kind = r.one_of(&["DISPLACEMENT", "VELOCITY", "ACCELERATION", "FORCE"])?;
            let mut markers = [None; 3];
            for (k, name) in ["I", "J", "RM"].iter().enumerate() {
                if r.flag(name) {
                    markers[k] = Some(marker(model, &r, name)?);
                }
            }
            if kind.is_some() && markers[0].is_none() {
                return Err(r.missing("I"));
            }
            if r.flag("ROUTINE") {
                return Err(Problem::new(
                    r.loc_of("ROUTINE"),
                    format!("REQUEST/{id}: ROUTINE (user subroutines) is not supported"),
                ));
            }
            let mut functions = Vec::new();
            for name in FUNCTIONS {
                let Some((text, _)) = r.expression(name) else {
                    continue;
                };
                if name == "FUNCTION" {
                    return Err(Problem::new(
                        text.loc_at(0),
                        format!(
                            "REQUEST/{id}: FUNCTION = USER(…) needs a user subroutine, which is not supported"
                        ),
                    ));
                }
                match parse_expr(&text.text) {
                    Ok(e) => check_function(low, model, id, name, text, &e)?,
                    Err(e) => {
                        let at = text.loc_at(e.offset);
                        match e.kind {
                            ExprErrorKind::UnknownFunction(_) => low.warning(
                                at,
                                format!(
                                    "REQUEST/{id}: {name}: {e}: this output column is written as 0"
                                ),
                            ),
                            _ => {
                                return Err(Problem::new(at, format!("REQUEST/{id}: {name}: {e}")));
                            }
                        }
                    }
                }
                functions.push((name, text.text.clone()));
            }
            Ok(Request {
                id,
                origin: low.origin(st.loc),
                kind,
                markers,
                comment: r.text("COMMENT"),
                functions,
            })
        })();
        if let Some(q) = low.ok(result) {
            model.requests.push(q);
        }
    }
}

/// Checks what a request function reads: markers, ORIENT types, elements and components.
fn check_function(
    low: &mut Lowering,
    model: &Model,
    id: u32,
    name: &str,
    text: &ExprText,
    e: &Expr,
) -> Result<(), Problem> {
    let at = |function: &str, argument: usize| {
        text.loc_at(argument_offset(&text.text, function, argument))
    };
    for m in e.marker_ids() {
        if !model.markers.contains_key(&m) {
            return Err(Problem::new(
                text.loc_at(0),
                format!("REQUEST/{id}: {name}: MARKER/{m} is not defined"),
            ));
        }
    }
    let mut problem = None;
    let mut unevaluated = None;
    e.walk(&mut |node| {
        if problem.is_some() {
            return;
        }
        match node {
            Expr::Orient([kind, component, ..]) => {
                if *kind != 27 {
                    problem = Some(Problem::new(
                        at("ORIENT", 0),
                        format!(
                            "REQUEST/{id}: {name}: ORIENT type {kind} is not supported (27, Euler parameters, is)"
                        ),
                    ));
                } else if !(1..=4).contains(component) {
                    problem = Some(Problem::new(
                        at("ORIENT", 1),
                        format!(
                            "REQUEST/{id}: {name}: ORIENT(27, …): component {component} is out of range: must be 1..=4"
                        ),
                    ));
                }
            }
            Expr::Element(kind, args) => {
                problem = check_element(model, id, name, *kind, *args, &at).err();
            }
            Expr::VarVal(v) if !model.variables.iter().any(|var| var.id == *v) => {
                problem = Some(Problem::new(
                    at("VARVAL", 0),
                    format!(
                        "REQUEST/{id}: {name}: VARVAL({v}): {}",
                        super::variables::missing_variable(model, *v)
                    ),
                ));
            }
            Expr::Measure(Measure::Vx | Measure::Vy | Measure::Vz | Measure::Vm, m)
                if m.get(3).is_some_and(|l| *l != 0) =>
            {
                unevaluated = Some("a velocity with a derivative frame");
            }
            _ => {}
        }
    });
    if let Some(p) = problem {
        return Err(p);
    }
    if let Some(what) = unevaluated {
        low.warning(
            text.loc_at(0),
            format!(
                "REQUEST/{id}: {name}: {what} is not evaluated in request output: this column is written as 0"
            ),
        );
    }
    Ok(())
}

/// Checks `KIND(id, jflag, comp, rm)`: the element exists, jflag is 0 or 1, the component is
/// 1..=8 and the element has it.
fn check_element(
    model: &Model,
    id: u32,
    name: &str,
    kind: ElementKind,
    [element, jflag, component, rm]: [u32; 4],
    at: &dyn Fn(&str, usize) -> crate::dataset::error::Loc,
) -> Result<(), Problem> {
    let label = kind.name();
    let call = format!("{label}({element},{jflag},{component},{rm})");
    let exists = match kind {
        ElementKind::Joint => model.joints.iter().any(|j| j.id == element),
        ElementKind::Motion => model.motions.iter().any(|m| m.id == element),
        ElementKind::Sforce => model.sforces.iter().any(|s| s.id == element),
    };
    if !exists {
        return Err(Problem::new(
            at(label, 0),
            format!("REQUEST/{id}: {name}: {call}: {label}/{element} is not defined"),
        ));
    }
    if jflag > 1 {
        return Err(Problem::new(
            at(label, 1),
            format!(
                "REQUEST/{id}: {name}: {call}: jflag {jflag} is out of range: must be 0 (I marker) or 1 (J marker)"
            ),
        ));
    }
    if !(1..=8).contains(&component) {
        return Err(Problem::new(
            at(label, 2),
            format!(
                "REQUEST/{id}: {name}: {call}: component {component} is out of range: must be 1..=8"
            ),
        ));
    }
    if rm != 0 && !model.markers.contains_key(&rm) {
        return Err(Problem::new(
            at(label, 3),
            format!("REQUEST/{id}: {name}: {call}: MARKER/{rm} is not defined"),
        ));
    }
    let rotational = kind == ElementKind::Sforce
        && model
            .sforces
            .iter()
            .any(|s| s.id == element && s.freedom == Freedom::Rotational);
    if rotational && component <= 4 {
        return Err(Problem::new(
            at(label, 2),
            format!(
                "REQUEST/{id}: {name}: {call}: Wrong component: {component}. No force in corresponding object (SFORCE/{element} is ROTATIONAL: it has torque components 5..=8 only)"
            ),
        ));
    }
    Ok(())
}

/// The character offset of argument `argument` (0-based) of the first call of `function` in
/// `text` (0 when not found).
fn argument_offset(text: &str, function: &str, argument: usize) -> usize {
    let upper: Vec<char> = text.to_ascii_uppercase().chars().collect();
    let name: Vec<char> = function.chars().collect();
    let Some(start) = (0..upper.len()).find(|&k| {
        upper[k..].starts_with(&name)
            && upper[k + name.len()..]
                .iter()
                .find(|c| !c.is_whitespace())
                .is_some_and(|c| *c == '(')
            && (k == 0 || !upper[k - 1].is_ascii_alphanumeric())
    }) else {
        return 0;
    };
    let mut depth = 0;
    let mut commas = 0;
    for (k, c) in upper.iter().enumerate().skip(start + name.len()) {
        match c {
            '(' => {
                depth += 1;
                if depth == 1 && argument == 0 {
                    return k + 1;
                }
            }
            ')' => depth -= 1,
            ',' if depth == 1 => {
                commas += 1;
                if commas == argument {
                    return k + 1;
                }
            }
            _ => {}
        }
    }
    start
}

/// GCON statements: the form `DM(a, b) − L` (L > 0, one of a and b the I marker) becomes a
/// distance constraint; any other function is refused by name.
pub(crate) fn lower_gcons(low: &mut Lowering, model: &mut Model, gcons: &[&Statement]) {
    for st in gcons {
        let Some((id, _)) = st.id else { continue };
        let r = Reader::new(st);
        let result = (|| -> Result<Gcon, Problem> {
            let i = marker(model, &r, "I")?;
            let (text, _) = r
                .expression("FUNCTION")
                .ok_or_else(|| r.missing("FUNCTION"))?;
            let e = parse_expr(&text.text).map_err(|e| {
                Problem::new(text.loc_at(e.offset), format!("GCON/{id}: FUNCTION: {e}"))
            })?;
            let unsupported = || {
                Problem::new(
                    text.loc_at(0),
                    format!(
                        "GCON/{id}: FUNCTION = {}: only a distance, DM(a, b) − L with L > 0 and I one of a and b, is supported",
                        text.text.trim()
                    ),
                )
            };
            let (a, b, length) = distance_form(&e).ok_or_else(unsupported)?;
            for m in [a, b] {
                if !model.markers.contains_key(&m) {
                    return Err(Problem::new(
                        text.loc_at(0),
                        format!("GCON/{id}: FUNCTION: MARKER/{m} is not defined"),
                    ));
                }
            }
            let j = match (a == i, b == i) {
                (true, false) => b,
                (false, true) => a,
                _ => return Err(unsupported()),
            };
            if model.markers[&i].part == model.markers[&j].part {
                return Err(Problem::new(
                    text.loc_at(0),
                    format!(
                        "GCON/{id}: MARKER/{i} and MARKER/{j} are both on PART/{}",
                        model.markers[&i].part
                    ),
                ));
            }
            Ok(Gcon {
                id,
                origin: low.origin(st.loc),
                i,
                j,
                length,
            })
        })();
        if let Some(g) = low.ok(result) {
            model.gcons.push(g);
        }
    }
}

/// `(a, b, L)` of `DM(a, b) − L` (also `DM(a, b) + (−L)` and `−L + DM(a, b)`), L > 0.
fn distance_form(e: &Expr) -> Option<(u32, u32, f64)> {
    use crate::expr::BinOp;
    let dm = |e: &Expr| match e {
        Expr::Measure(Measure::Dm, m) if m.len() == 2 && m[0] != 0 && m[1] != 0 => {
            Some((m[0], m[1]))
        }
        _ => None,
    };
    let constant = |e: &Expr| match e {
        Expr::Number(v) => Some(*v),
        Expr::Neg(inner) => match **inner {
            Expr::Number(v) => Some(-v),
            _ => None,
        },
        _ => None,
    };
    let (pair, length) = match e {
        Expr::Binary(BinOp::Sub, x, y) => (dm(x)?, constant(y)?),
        Expr::Binary(BinOp::Add, x, y) => match (dm(x), dm(y)) {
            (Some(p), _) => (p, -constant(y)?),
            (None, Some(p)) => (p, -constant(x)?),
            _ => return None,
        },
        _ => return None,
    };
    (length.is_finite() && length > 0.0).then_some((pair.0, pair.1, length))
}
