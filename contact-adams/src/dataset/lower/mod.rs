//! Lowering: parsed statements → a validated [`Model`], with every problem located.
//!
//! Statements may come in any order in a dataset, so lowering goes by dependency: UNITS,
//! PREFERENCES, ACCGRAV; PARTs; MARKERs; GRAPHICS (with CURVE and MATRIX); CONTACTs; joints,
//! motions, forces, variables, requests and settings; then the command file's commands.
//! A statement in error is left out of the model and reported; lowering goes on so one run
//! reports every problem.

mod bodies;
mod commands;
mod contact;
mod elements;
mod geometry;
mod reader;
mod requests;
mod variables;

pub use reader::{Problem, parse_number};

use crate::dataset::error::{Diagnostic, Loc, Origin};
use crate::dataset::parser::{ParsedFile, Statement};
use crate::model::{EquilibriumSettings, IntegratorSettings, Model};
use contact_core::{Preferences, Units, Vector3};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// Shared state while lowering one file.
pub(crate) struct Lowering {
    /// The file being lowered.
    pub file: Arc<Path>,
    /// The directory relative paths are resolved against.
    pub dir: PathBuf,
    /// Everything found so far.
    pub diagnostics: Vec<Diagnostic>,
}

impl Lowering {
    pub(crate) fn origin(&self, loc: Loc) -> Origin {
        Origin {
            file: self.file.clone(),
            loc,
        }
    }

    pub(crate) fn error(&mut self, problem: Problem) {
        let origin = self.origin(problem.loc);
        self.diagnostics
            .push(Diagnostic::error(origin, problem.message));
    }

    pub(crate) fn warning(&mut self, loc: Loc, message: impl Into<String>) {
        let origin = self.origin(loc);
        self.diagnostics.push(Diagnostic::warning(origin, message));
    }

    /// Records a problem from `result`, giving back the value when there was none.
    pub(crate) fn ok<T>(&mut self, result: Result<T, Problem>) -> Option<T> {
        match result {
            Ok(v) => Some(v),
            Err(p) => {
                self.error(p);
                None
            }
        }
    }
}

/// An empty model with Adams' defaults, before any statement is applied.
fn empty_model(title: String) -> Model {
    Model {
        title,
        units: Units::MKS,
        gravity: Vector3::zeros(),
        preferences: Preferences::default(),
        engine_preferences: Default::default(),
        parts: BTreeMap::new(),
        markers: BTreeMap::new(),
        graphics: BTreeMap::new(),
        contacts: Vec::new(),
        joints: Vec::new(),
        primitives: Vec::new(),
        gcons: Vec::new(),
        motions: Vec::new(),
        sforces: Vec::new(),
        variables: Vec::new(),
        requests: Vec::new(),
        integrator: IntegratorSettings::default(),
        equilibrium: EquilibriumSettings::default(),
        output_flags: Vec::new(),
        commands: Vec::new(),
        written: BTreeMap::new(),
        unevaluated_variables: BTreeMap::new(),
    }
}

fn report_parse(low: &mut Lowering, parsed: &ParsedFile) {
    for p in &parsed.problems {
        low.error(Problem::new(p.loc, p.message.clone()));
    }
    for st in &parsed.statements {
        if !st.spec.modelled {
            low.warning(
                st.loc,
                format!(
                    "{} is not modelled by contact: statement ignored",
                    st.spec.name
                ),
            );
            continue;
        }
        for arg in &st.args {
            if !arg.spec.modelled {
                low.warning(
                    arg.loc,
                    format!(
                        "{}: {} is not modelled by contact: argument ignored",
                        st.label(),
                        arg.spec.name
                    ),
                );
            }
        }
    }
}

/// Statements of one keyword in id order; a repeated id is an error (the later one is dropped).
fn by_id<'p>(low: &mut Lowering, parsed: &'p ParsedFile, name: &str) -> Vec<&'p Statement> {
    let mut seen: BTreeMap<u32, Loc> = BTreeMap::new();
    let mut out = Vec::new();
    for st in parsed.statements.iter().filter(|s| s.spec.name == name) {
        let Some((id, loc)) = st.id else { continue };
        if let Some(first) = seen.get(&id) {
            low.error(Problem::new(
                loc,
                format!(
                    "{name}/{id} is defined twice (first at line {})",
                    first.line
                ),
            ));
            continue;
        }
        seen.insert(id, st.loc);
        out.push(st);
    }
    out.sort_by_key(|s| s.id.map(|(id, _)| id));
    out
}

/// Statements without ids (UNITS/, PREFERENCES/, …), in file order.
pub(crate) fn singletons<'p>(parsed: &'p ParsedFile, name: &str) -> Vec<&'p Statement> {
    parsed
        .statements
        .iter()
        .filter(|s| s.spec.name == name)
        .collect()
}

/// Lowers a parsed dataset (and optionally a parsed command file) into a model. Problems are
/// returned beside the model; a model with errors is incomplete.
pub(crate) fn lower(
    adm: (&ParsedFile, &Path),
    acf: Option<(&ParsedFile, &Path)>,
) -> (Model, Vec<Diagnostic>) {
    let (parsed, path) = adm;
    let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    let mut low = Lowering {
        file: Arc::from(path),
        dir,
        diagnostics: Vec::new(),
    };
    report_parse(&mut low, parsed);
    let title = parsed
        .title
        .as_ref()
        .map(|t| t.text.clone())
        .unwrap_or_default();
    let mut model = empty_model(title);
    for st in &parsed.statements {
        *model.written.entry(st.spec.name).or_default() += 1;
    }
    if parsed.end.is_none() {
        let loc = parsed
            .statements
            .last()
            .map(|s| s.loc)
            .unwrap_or(Loc::new(1, 1));
        low.warning(loc, "the dataset has no END statement");
    }

    bodies::lower_settings(&mut low, &mut model, parsed);
    let parts = by_id(&mut low, parsed, "PART");
    bodies::lower_parts(&mut low, &mut model, &parts);
    let markers = by_id(&mut low, parsed, "MARKER");
    bodies::lower_markers(&mut low, &mut model, parsed, &markers);
    bodies::check_part_markers(&mut low, &model, &parts);

    let matrices = by_id(&mut low, parsed, "MATRIX");
    let curves = by_id(&mut low, parsed, "CURVE");
    let graphics = by_id(&mut low, parsed, "GRAPHICS");
    geometry::lower_graphics(&mut low, &mut model, &graphics, &curves, &matrices);

    let contacts = by_id(&mut low, parsed, "CONTACT");
    contact::lower_contacts(&mut low, &mut model, &contacts);

    let joints = by_id(&mut low, parsed, "JOINT");
    elements::lower_joints(&mut low, &mut model, &joints);
    let primitives = by_id(&mut low, parsed, "JPRIM");
    elements::lower_primitives(&mut low, &mut model, &primitives);
    let variables = by_id(&mut low, parsed, "VARIABLE");
    variables::lower_variables(&mut low, &mut model, &variables);
    let motions = by_id(&mut low, parsed, "MOTION");
    elements::lower_motions(&mut low, &mut model, &motions);
    let sforces = by_id(&mut low, parsed, "SFORCE");
    elements::lower_sforces(&mut low, &mut model, &sforces);
    let gcons = by_id(&mut low, parsed, "GCON");
    requests::lower_gcons(&mut low, &mut model, &gcons);
    let requests = by_id(&mut low, parsed, "REQUEST");
    requests::lower_requests(&mut low, &mut model, &requests);
    for st in singletons(parsed, "INTEGRATOR") {
        if let Some(settings) = elements::integrator(&mut low, st) {
            model.integrator = settings;
        }
    }
    for st in singletons(parsed, "EQUILIBRIUM") {
        if let Some(settings) = elements::equilibrium(&mut low, st) {
            model.equilibrium = settings;
        }
    }
    for name in ["OUTPUT", "RESULTS"] {
        for st in singletons(parsed, name) {
            model.output_flags.extend(
                st.args
                    .iter()
                    .filter(|a| a.values.is_empty())
                    .map(|a| a.spec.name),
            );
        }
    }

    let mut diagnostics = low.diagnostics;
    if let Some((acf_parsed, acf_path)) = acf {
        let mut low = Lowering {
            file: Arc::from(acf_path),
            dir: acf_path.parent().map(Path::to_path_buf).unwrap_or_default(),
            diagnostics: Vec::new(),
        };
        report_parse(&mut low, acf_parsed);
        commands::lower_commands(&mut low, &mut model, acf_parsed, path);
        diagnostics.extend(low.diagnostics);
    }
    (model, diagnostics)
}
