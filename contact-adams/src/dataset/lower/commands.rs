//! Command files (`.acf`): SIMULATE, LINEAR, INTEGRATOR, EQUILIBRIUM, ACTIVATE/DEACTIVATE,
//! ACCGRAV, PREFERENCES, OUTPUT, FILE and STOP.

use super::Lowering;
use super::bodies::{apply_preferences, gravity};
use super::elements::{equilibrium, integrator};
use super::reader::{Problem, Reader};
use crate::dataset::parser::{ParsedFile, Statement};
use crate::model::{Analysis, Command, Model, OutputSteps, SimulationSpan};
use crate::run::active::ElementClass;
use std::path::Path;

fn simulate(r: &Reader<'_>) -> Result<Command, Problem> {
    let analysis = match r.one_of(&[
        "DYNAMICS",
        "KINEMATICS",
        "STATICS",
        "TRANSIENT",
        "INITIAL_CONDITIONS",
    ])? {
        Some("DYNAMICS") => Analysis::Dynamics,
        Some("KINEMATICS") => Analysis::Kinematics,
        Some("STATICS") => Analysis::Statics,
        Some("TRANSIENT") => Analysis::Transient,
        Some(_) => Analysis::InitialConditions,
        None => {
            return Err(r.missing(
                "an analysis (DYNAMICS, KINEMATICS, STATICS, TRANSIENT or INITIAL_CONDITIONS)",
            ));
        }
    };
    let timed = matches!(
        analysis,
        Analysis::Dynamics | Analysis::Kinematics | Analysis::Transient
    );
    let span = match (r.number("END")?, r.number("DURATION")?) {
        (Some(_), Some(_)) => {
            return Err(Problem::new(
                r.loc_of("DURATION"),
                "SIMULATE: END and DURATION cannot both be given",
            ));
        }
        (Some(t), None) => Some(SimulationSpan::End(t)),
        (None, Some(d)) if d > 0.0 => Some(SimulationSpan::Duration(d)),
        (None, Some(d)) => {
            return Err(Problem::new(
                r.loc_of("DURATION"),
                format!("SIMULATE: DURATION = {d:?} is out of range: must be > 0"),
            ));
        }
        (None, None) if timed => return Err(r.missing("END or DURATION")),
        (None, None) => None,
    };
    let output = match (r.count_value("STEPS")?, r.number("DTOUT")?) {
        (Some(_), Some(_)) => {
            return Err(Problem::new(
                r.loc_of("DTOUT"),
                "SIMULATE: STEPS and DTOUT cannot both be given",
            ));
        }
        (Some(0), None) => {
            return Err(Problem::new(
                r.loc_of("STEPS"),
                "SIMULATE: STEPS = 0 is out of range: must be >= 1",
            ));
        }
        (Some(n), None) => Some(OutputSteps::Steps(n)),
        (None, Some(dt)) if dt > 0.0 => Some(OutputSteps::Interval(dt)),
        (None, Some(dt)) => {
            return Err(Problem::new(
                r.loc_of("DTOUT"),
                format!("SIMULATE: DTOUT = {dt:?} is out of range: must be > 0"),
            ));
        }
        (None, None) if timed => return Err(r.missing("STEPS or DTOUT")),
        (None, None) => None,
    };
    Ok(Command::Simulate {
        analysis,
        span,
        output,
    })
}

/// LINEAR/EIGENSOL [, NODAMPIN] [, NOVECTOR]. STATEMAT and MKB (state matrices and M, K, B
/// matrices written to files) are not modelled: an error at the keyword, so a run never
/// silently skips an analysis the command file asks for.
fn linear(r: &Reader<'_>) -> Result<Command, Problem> {
    for other in ["STATEMAT", "MKB"] {
        if r.flag(other) {
            return Err(Problem::new(
                r.loc_of(other),
                format!(
                    "LINEAR/{other} is not modelled: only LINEAR/EIGENSOL (eigenvalues) is available"
                ),
            ));
        }
    }
    if !r.flag("EIGENSOL") {
        return Err(r.missing("EIGENSOL (the only LINEAR analysis modelled)"));
    }
    Ok(Command::Linear {
        damping: !r.flag("NODAMPIN"),
    })
}

/// ACTIVATE/DEACTIVATE/class, ID = ids: a class the run can switch (JOINT, JPRIM, GCON,
/// MOTION, SFORCE, CONTACT) and ids of that class the model has. Any other class, an id the
/// model does not have, and a RANGE holding none of them are errors at the argument, so
/// `check` reports what `run` would refuse. `RANGE = first, last` adds every element of the
/// class with an id in between.
fn activate(
    low: &mut Lowering,
    model: &Model,
    r: &Reader<'_>,
    active: bool,
) -> Result<Command, Problem> {
    const CLASSES: [&str; 22] = [
        "JOINT",
        "JPRIM",
        "GCON",
        "CONTACT",
        "MOTION",
        "SFORCE",
        "SENSOR",
        "VARIABLE",
        "REQUEST",
        "BEAM",
        "BUSHING",
        "FIELD",
        "GFORCE",
        "SPRINGDAMPER",
        "VFORCE",
        "VTORQUE",
        "COUPLER",
        "DIFF",
        "LSE",
        "GSE",
        "TFSISO",
        "NFORCE",
    ];
    let verb = if active { "ACTIVATE" } else { "DEACTIVATE" };
    let keyword = r
        .one_of(&CLASSES)?
        .ok_or_else(|| r.missing(&format!("an element class ({})", ElementClass::list())))?;
    let class = ElementClass::from_keyword(keyword).ok_or_else(|| {
        Problem::new(
            r.get(keyword).map_or(r.loc_of(keyword), |a| a.loc),
            format!(
                "{verb}/{keyword}: {keyword} elements cannot be switched by this solver (it switches {})",
                ElementClass::list()
            ),
        )
    })?;
    let range = range_ids(model, r, class, &format!("{verb}/{keyword}"))?;
    let ids = match (r.ids("ID")?, range.is_empty()) {
        (Some(ids), _) => ids,
        (None, false) => Vec::new(),
        (None, true) => return Err(r.missing("ID or RANGE")),
    };
    let mut known = range;
    for (id, loc) in ids {
        if known.contains(&id) {
            continue;
        }
        if class.exists(model, id) {
            known.push(id);
        } else {
            low.error(Problem::new(
                loc,
                format!("{verb}/{keyword}: the model has no {keyword}/{id}"),
            ));
        }
    }
    Ok(Command::Activate {
        active,
        class: class.keyword(),
        ids: known,
    })
}

/// `RANGE = first, last`: every element of the class the model has with an id from `first` to
/// `last` (inclusive), as Adams reads it; none when RANGE is not given. Two ids, `first ≤ last`
/// and at least one element in between, else an error at the argument.
fn range_ids(
    model: &Model,
    r: &Reader<'_>,
    class: ElementClass,
    label: &str,
) -> Result<Vec<u32>, Problem> {
    let Some(bounds) = r.ids("RANGE")? else {
        return Ok(Vec::new());
    };
    let loc = r.loc_of("RANGE");
    let [(first, _), (last, last_loc)] = bounds[..] else {
        return Err(Problem::new(
            loc,
            format!(
                "{label}: RANGE takes two ids (first, last), got {}",
                bounds.len()
            ),
        ));
    };
    if last < first {
        return Err(Problem::new(
            last_loc,
            format!("{label}: RANGE = {first}, {last}: the last id must be >= the first"),
        ));
    }
    let ids: Vec<u32> = class
        .ids_of(model)
        .into_iter()
        .filter(|id| (first..=last).contains(id))
        .collect();
    if ids.is_empty() {
        return Err(Problem::new(
            loc,
            format!(
                "{label}: RANGE = {first}, {last}: the model has no {} with an id in it",
                class.keyword()
            ),
        ));
    }
    Ok(ids)
}

/// The model file a command file names (`file/model=name` or the first line) should be the
/// dataset being checked.
fn check_model_name(low: &mut Lowering, name: &str, loc: crate::dataset::Loc, adm: &Path) {
    let stem = adm
        .file_stem()
        .map(|s| s.to_string_lossy().to_string())
        .unwrap_or_default();
    let named = Path::new(name.trim());
    let named_stem = named
        .file_stem()
        .map(|s| s.to_string_lossy().to_string())
        .unwrap_or_default();
    if !named_stem.eq_ignore_ascii_case(&stem) {
        low.warning(
            loc,
            format!(
                "the command file names model '{}', but the dataset checked is '{}'",
                name.trim(),
                adm.display()
            ),
        );
    }
}

fn command(low: &mut Lowering, model: &mut Model, st: &Statement, adm: &Path) -> Option<Command> {
    let r = Reader::new(st);
    match st.spec.name {
        "SIMULATE" => low.ok(simulate(&r)),
        "LINEAR" => low.ok(linear(&r)),
        "ACTIVATE" | "DEACTIVATE" => {
            let result = activate(low, model, &r, st.spec.name == "ACTIVATE");
            low.ok(result)
                .filter(|c| !matches!(c, Command::Activate { ids, .. } if ids.is_empty()))
        }
        "INTEGRATOR" => integrator(low, st).map(Command::Integrator),
        "EQUILIBRIUM" => equilibrium(low, st).map(Command::Equilibrium),
        "ACCGRAV" => gravity(low, st).map(Command::Gravity),
        "STOP" => Some(Command::Stop),
        "PREFERENCES" => {
            apply_preferences(low, model, st);
            None
        }
        "OUTPUT" => {
            model
                .output_flags
                .extend(st.args.iter().map(|a| a.spec.name));
            None
        }
        "FILE" => {
            match low.ok(r.word("MODEL")) {
                Some(Some((name, loc))) => check_model_name(low, &name, loc, adm),
                Some(None) if r.flag("COMMAND") => low.warning(
                    st.loc,
                    "FILE/COMMAND: reading further command files is not modelled: ignored",
                ),
                Some(None) | None => {}
            }
            None
        }
        _ => None,
    }
}

/// Lowers a command file's commands into `model.commands`.
pub(crate) fn lower_commands(
    low: &mut Lowering,
    model: &mut Model,
    parsed: &ParsedFile,
    adm: &Path,
) {
    if let Some(first) = parsed.file_names.first() {
        check_model_name(low, &first.text, first.loc, adm);
    }
    for st in parsed.statements.iter().filter(|s| s.spec.modelled) {
        if let Some(c) = command(low, model, st, adm) {
            let origin = low.origin(st.loc);
            model.commands.push((origin, c));
        }
    }
    if parsed.end.is_none() {
        let loc = parsed.statements.last().map(|s| s.loc).unwrap_or_default();
        low.warning(loc, "the command file has no STOP command");
    }
}
