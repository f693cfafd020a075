//! The statements, commands and arguments the reader knows, and keyword abbreviation.
//!
//! Adams accepts any keyword shortened to a prefix that is unique among the keywords allowed in
//! that place (reference §7.1): `sim/dyn` is `SIMULATE/DYNAMICS`, `FUNC=` is `FUNCTION=`. An exact
//! match always wins over a longer keyword it prefixes (`I` in `MOTION` is `I`, not `ICDISP`),
//! and a few aliases that Adams documents are listed explicitly (`C=` for `COMMENT` in REQUEST).
//!
//! A statement or argument that Adams has but this product does not model is listed with
//! `modelled: false`: the reader accepts it and the model check reports it as ignored, once.

/// How an argument's value is written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Form {
    /// A bare keyword (`GROUND`, `IMPACT`).
    Flag,
    /// `ARG = v1[, v2 …]`: numbers, ids, words or colon lists.
    Values,
    /// `ARG = expression`, up to the end of the statement, a `\` or an in-line top-level comma.
    Expr,
    /// `ARG = free text` to the end of the line.
    Text,
}

/// One argument keyword.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ArgSpec {
    /// The full keyword, upper case.
    pub name: &'static str,
    /// How its value is written.
    pub form: Form,
    /// False for arguments accepted and reported as ignored.
    pub modelled: bool,
}

/// Whether a statement takes an id after its `/`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum IdRule {
    /// `NAME/id` is required.
    Required,
    /// No id: `NAME/` or `NAME/first_argument`.
    None,
}

/// One statement or command keyword and its arguments.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct StatementSpec {
    /// The full keyword, upper case.
    pub name: &'static str,
    /// Id rule.
    pub id: IdRule,
    /// Its arguments (empty for statements that are not modelled: they are skipped whole).
    pub args: &'static [ArgSpec],
    /// Explicit abbreviations: (alias, full argument name).
    pub aliases: &'static [(&'static str, &'static str)],
    /// False for statements accepted and reported as ignored.
    pub modelled: bool,
}

const fn flag(name: &'static str) -> ArgSpec {
    ArgSpec {
        name,
        form: Form::Flag,
        modelled: true,
    }
}
const fn vals(name: &'static str) -> ArgSpec {
    ArgSpec {
        name,
        form: Form::Values,
        modelled: true,
    }
}
const fn expr(name: &'static str) -> ArgSpec {
    ArgSpec {
        name,
        form: Form::Expr,
        modelled: true,
    }
}
const fn text(name: &'static str) -> ArgSpec {
    ArgSpec {
        name,
        form: Form::Text,
        modelled: true,
    }
}
const fn ignored(spec: ArgSpec) -> ArgSpec {
    ArgSpec {
        modelled: false,
        ..spec
    }
}
const fn stmt(name: &'static str, id: IdRule, args: &'static [ArgSpec]) -> StatementSpec {
    StatementSpec {
        name,
        id,
        args,
        aliases: &[],
        modelled: true,
    }
}
const fn not_modelled(name: &'static str) -> StatementSpec {
    StatementSpec {
        name,
        id: IdRule::None,
        args: &[],
        aliases: &[],
        modelled: false,
    }
}

use IdRule::{None as NoId, Required};

const UNITS: &[ArgSpec] = &[
    vals("FORCE"),
    vals("MASS"),
    vals("LENGTH"),
    vals("TIME"),
    vals("SYSTEM"),
    vals("UCF"),
];
const PART: &[ArgSpec] = &[
    flag("GROUND"),
    vals("MASS"),
    vals("CM"),
    vals("IM"),
    vals("IP"),
    vals("QG"),
    vals("REULER"),
    vals("XG"),
    vals("ZG"),
    vals("VX"),
    vals("VY"),
    vals("VZ"),
    vals("WX"),
    vals("WY"),
    vals("WZ"),
    ignored(vals("VM")),
    ignored(vals("WM")),
    ignored(vals("EXACT")),
    ignored(flag("PLANAR")),
    ignored(vals("MATERIAL")),
];
const MARKER: &[ArgSpec] = &[
    vals("PART"),
    vals("QP"),
    vals("REULER"),
    vals("ZP"),
    vals("XP"),
    flag("USEXP"),
    ignored(flag("FLOATING")),
    ignored(vals("RM")),
    vals("POINT_MASS"),
    vals("FLEX_BODY"),
    vals("NODE"),
    ignored(vals("NODE_LABEL")),
    ignored(vals("FE_PART")),
];
/// Display-only kinds (FORCE, SPDP, OUTLINE) keep their arguments as modelled: the whole
/// statement is reported as display-only instead.
const GRAPHICS: &[ArgSpec] = &[
    flag("ARC"),
    flag("CIRCLE"),
    flag("BOX"),
    flag("CYLINDER"),
    flag("FRUSTUM"),
    flag("ELLIPSOID"),
    flag("TORUS"),
    flag("PLANE"),
    flag("POINT"),
    flag("CURVE"),
    flag("EXTERNAL"),
    flag("FORCE"),
    flag("SPDP"),
    vals("OUTLINE"),
    vals("CM"),
    vals("CORNER"),
    vals("RM"),
    vals("RADIUS"),
    vals("RANGLE"),
    ignored(vals("SEG")),
    ignored(vals("SIDES")),
    vals("LENGTH"),
    vals("TOP"),
    vals("BOTTOM"),
    vals("X"),
    vals("Y"),
    vals("Z"),
    vals("XSCALE"),
    vals("YSCALE"),
    vals("ZSCALE"),
    vals("MAJOR_RADIUS"),
    vals("MINOR_RADIUS"),
    vals("XMIN"),
    vals("XMAX"),
    vals("YMIN"),
    vals("YMAX"),
    vals("CID"),
    vals("CRM"),
    vals("FILE"),
    vals("ELEMENT"),
    vals("FACETING_TOLERANCE"),
    vals("ETYPE"),
    vals("EID"),
    vals("EMARKER"),
    vals("I"),
    vals("J"),
    vals("COILS"),
    vals("DA"),
    vals("DB"),
    vals("DC"),
    vals("LC"),
    vals("LD"),
];
const CURVE: &[ArgSpec] = &[
    flag("OPEN"),
    flag("CLOSED"),
    vals("MATRIX"),
    flag("CURVE_POINTS"),
    vals("ORDER"),
    expr("FUNCTION"),
    vals("MINPAR"),
    vals("MAXPAR"),
    vals("ROUTINE"),
];
const MATRIX: &[ArgSpec] = &[
    vals("FULL"),
    flag("SPARSE"),
    vals("ROWS"),
    vals("COLUMNS"),
    vals("VALUES"),
    vals("I"),
    vals("J"),
    vals("FILE"),
    vals("NAME"),
];
const CONTACT: &[ArgSpec] = &[
    vals("IGEOM"),
    vals("JGEOM"),
    vals("TYPE"),
    flag("IMPACT"),
    flag("POISSON"),
    vals("STIFFNESS"),
    vals("DAMPING"),
    vals("DMAX"),
    vals("EXPONENT"),
    vals("PENALTY"),
    vals("RESTITUTION_COEFFICIENT"),
    flag("AUGMENTED_LAGRANGIAN_FORMULATION"),
    expr("NORMAL_FUNCTION"),
    vals("NORMAL_ROUTINE"),
    expr("FRICTION_FUNCTION"),
    vals("FRICTION_ROUTINE"),
    vals("IFLIP_GEOMETRY"),
    vals("JFLIP_GEOMETRY"),
    flag("IFLIP_NORMAL"),
    flag("JFLIP_NORMAL"),
    vals("COULOMB_FRICTION"),
    vals("MU_STATIC"),
    vals("MU_DYNAMIC"),
    vals("STICTION_TRANSITION_VELOCITY"),
    vals("FRICTION_TRANSITION_VELOCITY"),
    vals("STICTION"),
    ignored(vals("MAX_STICTION_DEFORMATION")),
];
const PREFERENCES: &[ArgSpec] = &[
    vals("CONTACT_GEOMETRY_LIBRARY"),
    vals("CONTACT_FACETING_TOLERANCE"),
    vals("NTHREADS"),
    ignored(vals("SIMFAIL")),
    ignored(vals("STATUS_MESSAGE")),
    ignored(vals("SOLVERBIAS")),
    ignored(vals("FLEX_LIMIT_CHECK")),
];
const ACCGRAV: &[ArgSpec] = &[vals("IGRAV"), vals("JGRAV"), vals("KGRAV")];
const JOINT: &[ArgSpec] = &[
    flag("CONVEL"),
    flag("CYLINDRICAL"),
    flag("FIXED"),
    flag("HOOKE"),
    flag("PLANAR"),
    flag("RACKPIN"),
    flag("REVOLUTE"),
    flag("SCREW"),
    flag("SPHERICAL"),
    flag("TRANSLATIONAL"),
    flag("UNIVERSAL"),
    vals("I"),
    vals("J"),
    vals("PD"),
    vals("PITCH"),
    ignored(vals("IC")),
    ignored(vals("ICTRAN")),
    ignored(vals("ICROT")),
];
const JPRIM: &[ArgSpec] = &[
    flag("ATPOINT"),
    flag("INLINE"),
    flag("INPLANE"),
    flag("ORIENTATION"),
    flag("PARALLEL_AXES"),
    flag("PERPENDICULAR"),
    vals("I"),
    vals("J"),
];
const MOTION: &[ArgSpec] = &[
    vals("JOINT"),
    flag("TRANSLATIONAL"),
    flag("ROTATIONAL"),
    flag("DISPLACEMENT"),
    flag("VELOCITY"),
    flag("ACCELERATION"),
    expr("FUNCTION"),
    vals("ICDISP"),
    vals("ICVEL"),
    vals("I"),
    vals("J"),
    flag("X"),
    flag("Y"),
    flag("Z"),
    flag("B1"),
    flag("B2"),
    flag("B3"),
    vals("ROUTINE"),
];
const SFORCE: &[ArgSpec] = &[
    vals("I"),
    vals("J"),
    flag("TRANSLATIONAL"),
    flag("ROTATIONAL"),
    flag("ACTIONONLY"),
    expr("FUNCTION"),
    vals("ROUTINE"),
];
const VARIABLE: &[ArgSpec] = &[expr("FUNCTION"), vals("IC"), vals("ROUTINE")];
const INTEGRATOR: &[ArgSpec] = &[
    flag("GSTIFF"),
    flag("WSTIFF"),
    flag("CONSTANT_BDF"),
    flag("ABAM"),
    flag("RKF45"),
    flag("HHT"),
    flag("NEWMARK"),
    flag("HASTIFF"),
    flag("I3"),
    flag("SI2"),
    flag("SI1"),
    vals("ERROR"),
    vals("HMAX"),
    vals("HMIN"),
    vals("HINIT"),
    vals("KMAX"),
    vals("MAXIT"),
    vals("CORRECTOR"),
    ignored(vals("PATTERN")),
    ignored(vals("ALPHA")),
    ignored(vals("BETA")),
    ignored(vals("GAMMA")),
    ignored(vals("INTERPOLATE")),
];
const EQUILIBRIUM: &[ArgSpec] = &[
    vals("ALIMIT"),
    vals("ERROR"),
    vals("IMBALANCE"),
    vals("MAXIT"),
    vals("STABILITY"),
    vals("TLIMIT"),
    flag("DYNAMIC"),
    flag("STATIC"),
    ignored(vals("PATTERN")),
    ignored(vals("ACCELERATION_ERROR")),
    ignored(vals("KINETIC_ENERGY_ERROR")),
    ignored(vals("GLOBAL_DAMPING")),
    ignored(vals("SETTLING_TIME")),
];
/// The CONTACT document writes `EQUILIBRIUM/DYNAMICS`; the FORTRAN page `DYNAMIC`.
const EQUILIBRIUM_ALIASES: &[(&str, &str)] = &[("DYNAMICS", "DYNAMIC")];
const OUTPUT: &[ArgSpec] = &[
    flag("REQSAVE"),
    flag("GRSAVE"),
    flag("NOSEPARATOR"),
    flag("SEPARATOR"),
    flag("NOPRINT"),
    flag("TELETYPE"),
    flag("YPR"),
];
const RESULTS: &[ArgSpec] = &[
    flag("XRF"),
    flag("FORMATTED"),
    flag("NOCONTACTS"),
    flag("NOACCELERATIONS"),
    flag("NOAPPLIEDFORCES"),
    flag("NODATASTRUCTURES"),
    flag("NODISPLACEMENTS"),
    flag("NOFLOATINGMARKERS"),
    flag("NOLINEAR"),
    flag("NOREACTIONFORCES"),
    flag("NOSYSTEMELEMENTS"),
    flag("NOTIRES"),
    flag("NOVELOCITIES"),
    flag("NOFLEXMODES"),
    vals("ROUNDOFF"),
    vals("SIGNIFICANT_DIGITS"),
    vals("ZERO_THRESHOLD"),
];
const REQUEST: &[ArgSpec] = &[
    flag("DISPLACEMENT"),
    flag("VELOCITY"),
    flag("ACCELERATION"),
    flag("FORCE"),
    vals("I"),
    vals("J"),
    vals("RM"),
    text("COMMENT"),
    text("TITLE"),
    expr("F1"),
    expr("F2"),
    expr("F3"),
    expr("F4"),
    expr("F5"),
    expr("F6"),
    expr("F7"),
    expr("F8"),
    expr("FUNCTION"),
    vals("ROUTINE"),
    ignored(vals("CNAMES")),
    ignored(vals("CLABELS")),
    ignored(vals("RESULTS_NAME")),
];
const SIMULATE: &[ArgSpec] = &[
    flag("DYNAMICS"),
    flag("KINEMATICS"),
    flag("STATICS"),
    flag("TRANSIENT"),
    flag("INITIAL_CONDITIONS"),
    flag("DISPLACEMENT"),
    flag("VELOCITY"),
    flag("ACCELERATION"),
    vals("END"),
    vals("DURATION"),
    vals("STEPS"),
    vals("DTOUT"),
];
const ACTIVATE: &[ArgSpec] = &[
    flag("JOINT"),
    flag("JPRIM"),
    flag("CONTACT"),
    flag("MOTION"),
    flag("SFORCE"),
    flag("SENSOR"),
    flag("VARIABLE"),
    flag("REQUEST"),
    vals("ID"),
    vals("RANGE"),
];
const FILE: &[ArgSpec] = &[vals("MODEL"), vals("COMMAND")];

/// Statements of a dataset (`.adm`).
pub const DATASET_STATEMENTS: &[StatementSpec] = &[
    stmt("UNITS", NoId, UNITS),
    stmt("PART", Required, PART),
    stmt("MARKER", Required, MARKER),
    stmt("GRAPHICS", Required, GRAPHICS),
    stmt("CURVE", Required, CURVE),
    stmt("MATRIX", Required, MATRIX),
    stmt("CONTACT", Required, CONTACT),
    stmt("PREFERENCES", NoId, PREFERENCES),
    stmt("ACCGRAV", NoId, ACCGRAV),
    stmt("JOINT", Required, JOINT),
    stmt("JPRIM", Required, JPRIM),
    stmt("MOTION", Required, MOTION),
    stmt("SFORCE", Required, SFORCE),
    stmt("VARIABLE", Required, VARIABLE),
    stmt("INTEGRATOR", NoId, INTEGRATOR),
    StatementSpec {
        aliases: EQUILIBRIUM_ALIASES,
        ..stmt("EQUILIBRIUM", NoId, EQUILIBRIUM)
    },
    stmt("OUTPUT", NoId, OUTPUT),
    stmt("RESULTS", NoId, RESULTS),
    StatementSpec {
        aliases: &[("C", "COMMENT"), ("D", "DISPLACEMENT")],
        ..stmt("REQUEST", Required, REQUEST)
    },
    not_modelled("ARRAY"),
    not_modelled("BEAM"),
    not_modelled("BUSHING"),
    not_modelled("CLEARANCE"),
    not_modelled("COUPLER"),
    not_modelled("CVCV"),
    not_modelled("DEBUG"),
    not_modelled("DIFF"),
    not_modelled("FEMDATA"),
    not_modelled("FIELD"),
    not_modelled("FLEX_BODY"),
    not_modelled("FRICTION"),
    not_modelled("GEAR"),
    not_modelled("GFORCE"),
    not_modelled("GSE"),
    not_modelled("KINEMATICS"),
    not_modelled("LIST"),
    not_modelled("LSE"),
    not_modelled("MFORCE"),
    not_modelled("MREQUEST"),
    not_modelled("NFORCE"),
    not_modelled("NOLIST"),
    not_modelled("PINPUT"),
    not_modelled("POINT_MASS"),
    not_modelled("POUTPUT"),
    not_modelled("PTCV"),
    not_modelled("SENSOR"),
    not_modelled("SPLINE"),
    not_modelled("SPRINGDAMPER"),
    not_modelled("STRING"),
    not_modelled("SURFACE"),
    not_modelled("TFSISO"),
    not_modelled("TIRE"),
    not_modelled("UCON"),
    not_modelled("VFORCE"),
    not_modelled("VTORQUE"),
];

/// Commands of a command file (`.acf`).
pub const COMMANDS: &[StatementSpec] = &[
    stmt("SIMULATE", NoId, SIMULATE),
    stmt("INTEGRATOR", NoId, INTEGRATOR),
    StatementSpec {
        aliases: EQUILIBRIUM_ALIASES,
        ..stmt("EQUILIBRIUM", NoId, EQUILIBRIUM)
    },
    stmt("ACTIVATE", NoId, ACTIVATE),
    stmt("DEACTIVATE", NoId, ACTIVATE),
    stmt("STOP", NoId, &[]),
    stmt("FILE", NoId, FILE),
    stmt("OUTPUT", NoId, OUTPUT),
    stmt("PREFERENCES", NoId, PREFERENCES),
    stmt("ACCGRAV", NoId, ACCGRAV),
    not_modelled("ARRAY"),
    not_modelled("BUSHING"),
    not_modelled("CONTROL"),
    not_modelled("DEBUG"),
    not_modelled("ENVIRONMENT"),
    not_modelled("HELP"),
    not_modelled("INFO"),
    not_modelled("LINEAR"),
    not_modelled("MARKER"),
    not_modelled("MENU"),
    not_modelled("MOTION"),
    not_modelled("PART"),
    not_modelled("RELOAD"),
    not_modelled("REQUEST"),
    not_modelled("RETURN"),
    not_modelled("SAVE"),
    not_modelled("SENSOR"),
    not_modelled("SFORCE"),
    not_modelled("SHOW"),
    not_modelled("SPLINE"),
    not_modelled("TIME"),
    not_modelled("VARIABLE"),
];

/// How a word matched a keyword table.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Match<T> {
    /// Exactly one keyword matches (exactly, by an alias, or as a unique prefix).
    Found(T),
    /// The word is a prefix of several keywords (listed, full names).
    Ambiguous(Vec<&'static str>),
    /// No keyword matches.
    Unknown,
}

/// Resolves `word` (any case) against `(name, item)` pairs: exact match, else unique prefix.
pub fn resolve<T: Copy>(word: &str, items: impl Iterator<Item = (&'static str, T)>) -> Match<T> {
    let upper = word.to_ascii_uppercase();
    if upper.is_empty() {
        return Match::Unknown;
    }
    let mut prefixed: Vec<(&'static str, T)> = Vec::new();
    for (name, item) in items {
        if name == upper {
            return Match::Found(item);
        }
        if name.starts_with(&upper) {
            prefixed.push((name, item));
        }
    }
    match prefixed.len() {
        0 => Match::Unknown,
        1 => Match::Found(prefixed[0].1),
        _ => Match::Ambiguous(prefixed.into_iter().map(|(n, _)| n).collect()),
    }
}

impl StatementSpec {
    /// Resolves an argument keyword of this statement (aliases first).
    pub fn argument(&self, word: &str) -> Match<&'static ArgSpec> {
        let upper = word.to_ascii_uppercase();
        for (alias, full) in self.aliases {
            if *alias == upper {
                if let Some(spec) = self.args.iter().find(|a| a.name == *full) {
                    return Match::Found(spec);
                }
            }
        }
        resolve(word, self.args.iter().map(|a| (a.name, a)))
    }
}

/// Resolves a statement (or command) keyword in `table`.
pub fn statement(word: &str, table: &'static [StatementSpec]) -> Match<&'static StatementSpec> {
    resolve(word, table.iter().map(|s| (s.name, s)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn abbreviations_resolve_to_unique_prefixes() {
        let sim = statement("sim", COMMANDS);
        assert!(matches!(sim, Match::Found(s) if s.name == "SIMULATE"));
        let Match::Found(motion) = statement("MOTION", DATASET_STATEMENTS) else {
            panic!("MOTION not found")
        };
        assert!(matches!(motion.argument("func"), Match::Found(a) if a.name == "FUNCTION"));
        assert!(matches!(motion.argument("I"), Match::Found(a) if a.name == "I"));
        assert!(matches!(motion.argument("ROTATION"), Match::Found(a) if a.name == "ROTATIONAL"));
        assert_eq!(
            motion.argument("IC"),
            Match::Ambiguous(vec!["ICDISP", "ICVEL"])
        );
        assert_eq!(motion.argument("BOGUS"), Match::Unknown);
        let Match::Found(request) = statement("REQ", DATASET_STATEMENTS) else {
            panic!("REQUEST not found")
        };
        assert!(matches!(request.argument("c"), Match::Found(a) if a.name == "COMMENT"));
    }

    #[test]
    fn every_table_has_unique_names() {
        for table in [DATASET_STATEMENTS, COMMANDS] {
            for (k, s) in table.iter().enumerate() {
                assert!(
                    table[k + 1..].iter().all(|o| o.name != s.name),
                    "{}",
                    s.name
                );
                for (m, a) in s.args.iter().enumerate() {
                    assert!(
                        s.args[m + 1..].iter().all(|o| o.name != a.name),
                        "{}: {}",
                        s.name,
                        a.name
                    );
                }
            }
        }
    }
}
