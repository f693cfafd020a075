//! VARIABLE statements: their FUNCTIONs, VARVAL references between them and their cycles,
//! and the variables left out because a function they call is not evaluated here.

use super::Lowering;
use super::reader::{Problem, Reader};
use crate::dataset::parser::Statement;
use crate::expr::{ExprErrorKind, parse_expr};
use crate::model::{Model, Variable};

/// Why VARIABLE/`v` has no value: not defined, or its FUNCTION calls a function this solver
/// does not evaluate.
pub(super) fn missing_variable(model: &Model, v: u32) -> String {
    match model.unevaluated_variables.get(&v) {
        Some(why) => format!("VARIABLE/{v} has no value here: its FUNCTION has an {why}"),
        None => format!("VARIABLE/{v} is not defined"),
    }
}

/// VARIABLE statements: all ids are known first, so variables may read each other.
pub(crate) fn lower_variables(low: &mut Lowering, model: &mut Model, variables: &[&Statement]) {
    // Every declared id is known before any function is checked, so a VARVAL may name a
    // variable defined later in the file.
    let declared: Vec<u32> = variables
        .iter()
        .filter_map(|s| s.id.map(|(id, _)| id))
        .collect();
    let mut lowered = Vec::new();
    let mut unevaluated = Vec::new();
    for st in variables {
        let Some((id, _)) = st.id else { continue };
        let r = Reader::new(st);
        let result = (|| -> Result<Option<Variable>, Problem> {
            if r.flag("ROUTINE") {
                return Err(Problem::new(
                    r.loc_of("ROUTINE"),
                    format!("VARIABLE/{id}: ROUTINE (user subroutines) is not supported"),
                ));
            }
            let (text, loc) = r
                .expression("FUNCTION")
                .ok_or_else(|| r.missing("FUNCTION"))?;
            let f = parse_expr(&text.text).map_err(|e| {
                let problem = Problem::new(
                    text.loc_at(e.offset),
                    format!("VARIABLE/{id}: FUNCTION: {e}"),
                );
                match e.kind {
                    ExprErrorKind::UnknownFunction(name) => Err((problem, name)),
                    _ => Ok(problem),
                }
            });
            let f = match f {
                Ok(f) => f,
                Err(Ok(problem)) => return Err(problem),
                Err(Err((problem, function))) => {
                    unevaluated.push((id, problem, function));
                    return Ok(None);
                }
            };
            for m in f.marker_ids() {
                if !model.markers.contains_key(&m) {
                    return Err(Problem::new(
                        loc,
                        format!("VARIABLE/{id}: FUNCTION: MARKER/{m} is not defined"),
                    ));
                }
            }
            for v in f.variable_ids() {
                if !declared.contains(&v) {
                    return Err(Problem::new(
                        loc,
                        format!(
                            "VARIABLE/{id}: FUNCTION: VARVAL({v}): VARIABLE/{v} is not defined"
                        ),
                    ));
                }
            }
            Ok(Some(Variable {
                id,
                origin: low.origin(st.loc),
                function: f,
                initial_value: r.number("IC")?,
            }))
        })();
        if let Some(Some(v)) = low.ok(result) {
            lowered.push(v);
        }
    }
    leave_out_unevaluated(low, model, &mut lowered, unevaluated);
    report_variable_cycles(low, &lowered);
    model.variables = lowered;
}

/// VARIABLEs whose FUNCTIONs read each other through VARVAL in a cycle have no value: each
/// cycle is an error at the VARIABLE with the smallest id in it, naming the cycle
/// (`VARIABLE/1 → VARIABLE/2 → VARIABLE/1`).
fn report_variable_cycles(low: &mut Lowering, variables: &[Variable]) {
    let reads: std::collections::BTreeMap<u32, Vec<u32>> = variables
        .iter()
        .map(|v| (v.id, v.function.variable_ids()))
        .collect();
    let mut reported = std::collections::BTreeSet::new();
    for v in variables {
        // Depth-first from v, looking for a path back to v.
        let mut stack = vec![(v.id, vec![v.id])];
        let mut visited = std::collections::BTreeSet::new();
        while let Some((at, path)) = stack.pop() {
            for &next in reads.get(&at).map_or(&[][..], Vec::as_slice) {
                if next == v.id {
                    let smallest = path.iter().min().copied().unwrap_or(v.id);
                    if smallest == v.id && reported.insert(v.id) {
                        let names: Vec<String> = path
                            .iter()
                            .chain([&v.id])
                            .map(|id| format!("VARIABLE/{id}"))
                            .collect();
                        low.error(Problem::new(
                            v.origin.loc,
                            format!(
                                "VARIABLE/{}: FUNCTION: the variables read each other in a cycle ({}): none has a value",
                                v.id,
                                names.join(" → ")
                            ),
                        ));
                    }
                } else if visited.insert(next) {
                    let mut longer = path.clone();
                    longer.push(next);
                    stack.push((next, longer));
                }
            }
        }
    }
}

/// An unsupported function is an error only where a value is needed: each VARIABLE in
/// `unevaluated` (id, the parse problem, the function) is left out with a warning, and so is
/// every VARIABLE of `lowered` that reads one through VARVAL; the uses are the errors.
fn leave_out_unevaluated(
    low: &mut Lowering,
    model: &mut Model,
    lowered: &mut Vec<Variable>,
    unevaluated: Vec<(u32, Problem, String)>,
) {
    for (id, problem, function) in unevaluated {
        low.warning(
            problem.loc,
            format!(
                "{}: the variable has no value: an error wherever it is used",
                problem.message
            ),
        );
        model
            .unevaluated_variables
            .insert(id, format!("unsupported function {function}"));
    }
    let reads_unevaluated = |v: &Variable, model: &Model| {
        v.function
            .variable_ids()
            .into_iter()
            .find(|u| model.unevaluated_variables.contains_key(u))
    };
    while let Some(k) = lowered
        .iter()
        .position(|v| reads_unevaluated(v, model).is_some())
    {
        let v = lowered.remove(k);
        let u = reads_unevaluated(&v, model).unwrap_or(v.id);
        low.warning(
            v.origin.loc,
            format!(
                "VARIABLE/{}: FUNCTION: VARVAL({u}): {}: the variable has no value: an error wherever it is used",
                v.id,
                missing_variable(model, u)
            ),
        );
        model
            .unevaluated_variables
            .insert(v.id, format!("unsupported function, through VARVAL({u})"));
    }
}
