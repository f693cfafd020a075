//! Unit tests of the statement parser.
use super::*;

fn one(text: &str) -> Statement {
    let parsed = parse(&format!("title\n{text}\n"), FileKind::Dataset);
    assert!(parsed.problems.is_empty(), "{:?}", parsed.problems);
    assert_eq!(parsed.statements.len(), 1);
    parsed.statements[0].clone()
}

fn atoms(arg: &Arg) -> Vec<String> {
    arg.values
        .iter()
        .map(|v| match &v.kind {
            ValueKind::Atom(s) | ValueKind::Text(s) => s.clone(),
            ValueKind::Expr(e) => e.text.clone(),
        })
        .collect()
}

#[test]
fn ids_lists_and_flags() {
    let s = one("PART/02, MASS = 1\n, CM = 0201, IP = 0.04, 0.1\n, 0.1, GROUND");
    assert_eq!(s.id, Some((2, Loc::new(2, 6))));
    let names: Vec<_> = s.args.iter().map(|a| a.spec.name).collect();
    assert_eq!(names, ["MASS", "CM", "IP", "GROUND"]);
    assert_eq!(atoms(&s.args[2]), ["0.04", "0.1", "0.1"]);
    assert_eq!(s.args[2].values[2].loc, Loc::new(4, 3));
}

#[test]
fn quoted_names_make_a_list_over_continuation_lines() {
    // As Adams View writes a REQUEST's column names and labels (the FRS5 model).
    let s = one(
        "REQUEST/9\n, CNAMES = \"S1_beam18\", \"S1_beam19\"\n, \"S1_beam20\"\n, CLABELS = \"(PSI)\", \"(PSI)\"\n, \"(PSI)\"\n, I = 497",
    );
    let names: Vec<_> = s.args.iter().map(|a| a.spec.name).collect();
    assert_eq!(names, ["CNAMES", "CLABELS", "I"]);
    assert_eq!(
        atoms(&s.args[0]),
        ["\"S1_beam18\"", "\"S1_beam19\"", "\"S1_beam20\""]
    );
    assert_eq!(atoms(&s.args[1]), ["\"(PSI)\"", "\"(PSI)\"", "\"(PSI)\""]);
    assert_eq!(s.args[0].values[2].loc, Loc::new(4, 3));
    // A flag of RESULTS that Adams View writes.
    let s = one("RESULTS/\n, FORMATTED\n, NOREQUESTS\n, NOCONTACTS");
    let names: Vec<_> = s.args.iter().map(|a| a.spec.name).collect();
    assert_eq!(names, ["FORMATTED", "NOREQUESTS", "NOCONTACTS"]);
}

#[test]
fn expressions_end_at_backslash_comma_or_keyword_line() {
    let s =
        one("REQUEST/04, F2=ORIENT(27,1,0201,0101)\\F3=ORIENT(27,2,0201,0101),C=EULER PARAMETERS");
    assert_eq!(atoms(&s.args[0]), ["ORIENT(27,1,0201,0101)"]);
    assert_eq!(atoms(&s.args[1]), ["ORIENT(27,2,0201,0101)"]);
    assert_eq!(atoms(&s.args[2]), ["EULER PARAMETERS"]);
    let s = one("MOTION/1, JOINT=1, FUNCTION =\n, 30.0d *\n, time\n, ICDISP = 0");
    assert_eq!(atoms(&s.args[1]), ["30.0d *  time"]);
    let ValueKind::Expr(e) = &s.args[1].values[0].kind else {
        panic!("not an expression")
    };
    assert_eq!(e.loc_at(0), Loc::new(3, 3));
    assert_eq!(e.loc_at(9), Loc::new(4, 3));
    assert_eq!(s.args[2].spec.name, "ICDISP");
}

#[test]
fn errors_carry_locations() {
    let parsed = parse(
        "t\nPART/1, MA = 1\nPRT/2\nMARKER/x\nMOTION/1, IC=1\n",
        FileKind::Dataset,
    );
    let got: Vec<_> = parsed
        .problems
        .iter()
        .map(|p| format!("{}: {}", p.loc, p.message))
        .collect();
    assert_eq!(
        got,
        [
            "2:9: PART/1: ambiguous abbreviation 'MA': could be MASS, MATERIAL",
            "3:1: unknown statement 'PRT'",
            "4:8: MARKER/x: the id must be a positive integer",
            "5:11: MOTION/1: ambiguous abbreviation 'IC': could be ICDISP, ICVEL",
        ]
    );
}
