//! The committed header `include/rmfsurf.h` must be exactly what the pinned cbindgen
//! generates from the sources. Regenerate it with
//! `RMFSURF_BLESS_HEADER=1 cargo test --test header`.
//!
//! Its documentation is checked here too, without Doxygen (which `scripts/docs-site` runs):
//! every function has `\since`, every function, type and constant is `\ingroup`ed in a group
//! the header defines, and every parameter of every function has an `@param`, with no
//! `@param` naming something that is not a parameter.

use std::collections::BTreeSet;
use std::path::Path;

/// Deprecation the compiler sees: functions with `#[deprecated(note = ...)]` are declared
/// with `RMF_DEPRECATED(note)`, which this defines for GCC, Clang and MSVC unless the
/// includer has (`#define RMF_DEPRECATED(note)` before the include silences it).
const DEPRECATION: &str = "
/* Marks the functions kept for compatibility; each note names the replacement. */
#if !defined(RMF_DEPRECATED)
#if defined(__GNUC__) || defined(__clang__)
#define RMF_DEPRECATED(note) __attribute__((deprecated(note)))
#elif defined(_MSC_VER)
#define RMF_DEPRECATED(note) __declspec(deprecated(note))
#else
#define RMF_DEPRECATED(note)
#endif
#endif";

/// cbindgen.toml with the deprecation macro. It is added here, not in cbindgen.toml, because
/// maturin generates the Python package's cffi declarations from cbindgen.toml, and cffi
/// reads no preprocessor conditionals.
fn config(root: &Path) -> cbindgen::Config {
    let mut config =
        cbindgen::Config::from_file(root.join("cbindgen.toml")).expect("cbindgen.toml parses");
    config.after_includes = Some(DEPRECATION.into());
    config.function.deprecated_with_note = Some("RMF_DEPRECATED({})".into());
    config
}

#[test]
fn committed_header_is_what_cbindgen_generates() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let config = config(root);
    let bindings = cbindgen::Builder::new()
        .with_crate(root)
        .with_config(config)
        .generate()
        .expect("cbindgen generates the header");
    let mut generated = Vec::new();
    bindings.write(&mut generated);
    let path = root.join("../include/rmfsurf.h");
    if std::env::var_os("RMFSURF_BLESS_HEADER").is_some() {
        std::fs::write(&path, &generated).expect("header written");
        return;
    }
    let committed = std::fs::read(&path).unwrap_or_default();
    assert!(
        committed == generated,
        "include/rmfsurf.h is stale: regenerate it with `RMFSURF_BLESS_HEADER=1 cargo test --test header` and commit it"
    );
}

/// The committed header's documentation is complete (the other test keeps it equal to
/// what the sources generate, so its gaps are the sources').
#[test]
fn every_item_of_the_header_is_grouped_and_every_function_has_since_and_its_params() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../include/rmfsurf.h");
    let header = std::fs::read_to_string(&path).expect("include/rmfsurf.h is readable");
    let (items, problems) = check_header(&header, crate_version());
    assert!(
        problems.is_empty(),
        "{} documentation gaps in include/rmfsurf.h (fix the doc comments in capi/src and regenerate):\n{}",
        problems.len(),
        problems.join("\n")
    );
    // The parser found the header's declarations: a parse that saw nothing would pass.
    let functions = items.iter().filter(|i| i.kind == Kind::Function).count();
    assert!(functions >= 90, "only {functions} functions parsed");
    assert!(items.iter().any(|i| i.name == "rmf_wire_sweep"));
    assert!(items
        .iter()
        .any(|i| i.name == "RMF_OK" || i.name == "RmfStatus"));
    assert!(items.iter().any(|i| i.name == "RMF_CONE_RULE_GIVEN"));
}

/// The check finds each kind of gap in a synthetic header: it can fail.
#[test]
fn the_documentation_check_finds_each_kind_of_gap() {
    let groups = "/**\n * \\defgroup rmf_curves Curves\n */\n\n";
    let good = "/**\n * Evaluates.\n *\n * @param[in] curve The curve.\n * @param[in] t, u Parameters.\n * @param[out] out Receives it.\n * \\since 0.1\n * \\ingroup rmf_curves\n */\nRmfStatus rmf_eval(const struct RmfCurve *curve,\n                  double t,\n                  double u,\n                  struct RmfVec3 *out);\n";
    let (items, problems) = check_header(&format!("{groups}{good}"), (0, 2));
    assert_eq!(problems, Vec::<String>::new());
    assert_eq!(items.len(), 1);
    assert_eq!(items[0].params, ["curve", "t", "u", "out"]);

    let cases = [
        (good.replace(" * \\since 0.1\n", ""), "rmf_eval: no \\since"),
        (
            good.replace("\\since 0.1", "\\since 0.3"),
            "rmf_eval: \\since 0.3 is after",
        ),
        (
            good.replace(" * \\ingroup rmf_curves\n", ""),
            "rmf_eval: in no group",
        ),
        (
            good.replace("\\ingroup rmf_curves", "\\ingroup rmf_nothing"),
            "rmf_eval: group rmf_nothing is not defined",
        ),
        (
            good.replace("@param[in] t, u", "@param[in] t"),
            "rmf_eval: parameter u has no @param",
        ),
        (
            good.replace(" * @param[out] out Receives it.\n", ""),
            "rmf_eval: parameter out has no @param",
        ),
        (
            good.replace("@param[out] out", "@param[out] result"),
            "rmf_eval: @param result is not a parameter",
        ),
        (
            good.replace("/**\n * Evaluates.", "/*\n * Evaluates."),
            "rmf_eval: no doc comment",
        ),
    ];
    for (text, expected) in cases {
        let (_, problems) = check_header(&format!("{groups}{text}"), (0, 2));
        assert!(
            problems.iter().any(|p| p.starts_with(expected)),
            "expected a problem starting with {expected:?}, got {problems:?} for\n{text}"
        );
    }

    // A type and a constant without a group; with groups they pass.
    let types = "/**\n * A vector.\n */\ntypedef struct RmfVec3 {\n  double x;\n} RmfVec3;\n\n/**\n * One.\n */\n#define RMF_ONE 1\n";
    let (items, problems) = check_header(&format!("{groups}{types}"), (0, 2));
    assert_eq!(items.len(), 2);
    assert_eq!(
        problems,
        [
            "RmfVec3: in no group (\\ingroup)",
            "RMF_ONE: in no group (\\ingroup)"
        ]
    );
    let grouped = types.replace(" */\n", " * \\ingroup rmf_curves\n */\n");
    let (_, problems) = check_header(&format!("{groups}{grouped}"), (0, 2));
    assert_eq!(problems, Vec::<String>::new());
}

/// major.minor of the crate: no `\since` may name a later version.
fn crate_version() -> (u32, u32) {
    let mut parts = env!("CARGO_PKG_VERSION")
        .split('.')
        .map(|p| p.parse::<u32>().unwrap());
    (parts.next().unwrap(), parts.next().unwrap())
}

#[derive(Debug, PartialEq, Eq, Clone, Copy)]
enum Kind {
    Function,
    Type,
    Constant,
}

#[derive(Debug)]
struct Item {
    kind: Kind,
    name: String,
    params: Vec<String>,
}

/// The top-level declarations of a cbindgen header with their doc comments, and the gaps
/// of their documentation, one line each ("name: what is missing").
fn check_header(header: &str, version: (u32, u32)) -> (Vec<Item>, Vec<String>) {
    let lines: Vec<&str> = header.lines().collect();
    let mut groups = BTreeSet::new();
    let mut items = Vec::new();
    let mut problems = Vec::new();
    let mut doc: Option<Vec<String>> = None;
    let mut seen = BTreeSet::new();
    let mut i = 0;
    while i < lines.len() {
        let line = lines[i];
        if line.starts_with("/**") {
            let mut text = Vec::new();
            let first = line.trim_start_matches("/**");
            if let Some(rest) = first.strip_suffix("*/") {
                text.push(rest.trim().to_string());
            } else {
                text.push(first.trim().to_string());
                i += 1;
                while i < lines.len() && !lines[i].trim_start().starts_with("*/") {
                    let l = lines[i].trim_start();
                    text.push(l.strip_prefix('*').unwrap_or(l).trim().to_string());
                    i += 1;
                }
            }
            let defines: Vec<String> = text
                .iter()
                .filter_map(|l| l.strip_prefix("\\defgroup "))
                .filter_map(|rest| rest.split_whitespace().next().map(str::to_string))
                .collect();
            if defines.is_empty() {
                doc = Some(text);
            } else {
                groups.extend(defines);
            }
            i += 1;
            continue;
        }
        let declaration = if let Some(rest) = line.strip_prefix("#define ") {
            let name = rest.split_whitespace().next().unwrap_or("").to_string();
            // The include guard and the deprecation attribute are no constants.
            (name != "RMFSURF_H" && !name.starts_with("RMF_DEPRECATED("))
                .then(|| (Kind::Constant, name, Vec::new()))
        } else if line.starts_with("typedef ")
            || line.starts_with("enum ")
            || line.starts_with("struct ")
        {
            let name = type_name(line);
            // `typedef enum RmfStatus RmfStatus;` completes the enum already seen.
            (!seen.contains(&name)).then(|| (Kind::Type, name, Vec::new()))
        } else if line.starts_with(|c: char| c.is_ascii_alphabetic())
            && line.contains('(')
            && !line.starts_with("extern ")
        {
            // A deprecated function's attribute stands on the line above its prototype.
            if line.starts_with("RMF_DEPRECATED(") {
                i += 1;
            }
            let mut prototype = lines[i].to_string();
            while !prototype.trim_end().ends_with(';') && i + 1 < lines.len() {
                i += 1;
                prototype.push(' ');
                prototype.push_str(lines[i].trim());
            }
            let (name, params) = parse_prototype(&prototype);
            Some((Kind::Function, name, params))
        } else {
            None
        };
        if let Some((kind, name, params)) = declaration {
            seen.insert(name.clone());
            match doc.take() {
                None => problems.push(format!("{name}: no doc comment")),
                Some(text) => check_item(kind, &name, &params, &text, version, &mut problems),
            }
            items.push(Item { kind, name, params });
        } else if !line.trim().is_empty() && !line.starts_with(char::is_whitespace) {
            // A doc comment belongs to the declaration right after it.
            if !line.starts_with('}') && !line.starts_with('#') {
                doc = None;
            }
        }
        i += 1;
    }
    // Groups are checked once all are known (their definitions lead the header, but the
    // check does not rely on that).
    let mut resolved = Vec::new();
    for p in problems {
        match p.strip_prefix("\u{0}group ") {
            Some(rest) => {
                let (name, group) = rest.split_once(' ').unwrap();
                if !groups.contains(group) {
                    resolved.push(format!("{name}: group {group} is not defined (\\defgroup)"));
                }
            }
            None => resolved.push(p),
        }
    }
    (items, resolved)
}

/// The name a type declaration line declares.
fn type_name(line: &str) -> String {
    let line = line.trim_end_matches(['{', ' ', ';']);
    if let Some(start) = line.find("(*") {
        // typedef void (*Name)(...)
        return line[start + 2..]
            .split(')')
            .next()
            .unwrap_or("")
            .to_string();
    }
    line.split_whitespace().last().unwrap_or("").to_string()
}

/// The name and the parameter names of a C prototype `Ret name(T a, U *b);`.
fn parse_prototype(prototype: &str) -> (String, Vec<String>) {
    let open = prototype.find('(').unwrap();
    let close = prototype.rfind(')').unwrap();
    let name = prototype[..open]
        .split_whitespace()
        .last()
        .unwrap_or("")
        .trim_start_matches('*');
    let inner = prototype[open + 1..close].trim();
    assert!(
        !inner.contains('('),
        "{name}: a function-pointer parameter; give its type a typedef (the check reads names after types)"
    );
    let params = if inner.is_empty() || inner == "void" {
        Vec::new()
    } else {
        inner
            .split(',')
            .map(|p| {
                let p = p.split('[').next().unwrap();
                let word = p
                    .rsplit(|c: char| c.is_whitespace() || c == '*')
                    .next()
                    .unwrap();
                word.to_string()
            })
            .collect()
    };
    (name.to_string(), params)
}

/// The gaps of one item's doc comment: `\since` (functions; not after `version`), a group,
/// the `@param`s (functions). Group names are resolved by the caller.
fn check_item(
    kind: Kind,
    name: &str,
    params: &[String],
    doc: &[String],
    version: (u32, u32),
    problems: &mut Vec<String>,
) {
    let groups: Vec<&str> = doc
        .iter()
        .filter_map(|l| l.strip_prefix("\\ingroup "))
        .flat_map(str::split_whitespace)
        .collect();
    match groups.as_slice() {
        [] => problems.push(format!("{name}: in no group (\\ingroup)")),
        [group] => problems.push(format!("\u{0}group {name} {group}")),
        _ => problems.push(format!("{name}: in several groups {groups:?}")),
    }
    if kind != Kind::Function {
        return;
    }
    let since: Vec<&str> = doc
        .iter()
        .filter_map(|l| l.strip_prefix("\\since "))
        .collect();
    match since.as_slice() {
        [] => problems.push(format!("{name}: no \\since")),
        [v] => {
            let parsed = v
                .trim()
                .split_once('.')
                .and_then(|(a, b)| Some((a.parse::<u32>().ok()?, b.parse::<u32>().ok()?)));
            match parsed {
                None => problems.push(format!("{name}: \\since {v} is not major.minor")),
                Some(s) if s > version => problems.push(format!(
                    "{name}: \\since {v} is after the crate's version {}.{}",
                    version.0, version.1
                )),
                Some(_) => {}
            }
        }
        _ => problems.push(format!("{name}: several \\since")),
    }
    let mut documented = Vec::new();
    for line in doc {
        let Some(rest) = line
            .strip_prefix("@param")
            .or_else(|| line.strip_prefix("\\param"))
        else {
            continue;
        };
        let mut rest = rest.trim_start();
        if rest.starts_with('[') {
            rest = rest[rest.find(']').map_or(rest.len(), |e| e + 1)..].trim_start();
        }
        // "a, b, c Text": the names up to the first one not followed by a comma.
        for word in rest.split_whitespace() {
            let bare = word.trim_end_matches(',');
            documented.push(bare.to_string());
            if !word.ends_with(',') {
                break;
            }
        }
    }
    for p in params {
        if !documented.contains(p) {
            problems.push(format!("{name}: parameter {p} has no @param"));
        }
    }
    for d in &documented {
        if !params.contains(d) {
            problems.push(format!("{name}: @param {d} is not a parameter"));
        }
    }
}
