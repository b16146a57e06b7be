//! What the published packages say about the project agrees with the one place it is
//! written, the crate's manifest (Cargo.toml): the repository and documentation addresses
//! in the Python package's metadata (python/pyproject.toml) and page (python/PACKAGE.md), in
//! the FreeCAD addon's manifest (freecad/package.xml) and README, and the license texts the
//! licence expression names. The distributions themselves are checked in python.rs (wheel
//! and sdist) and workbench.rs (the addon tree, with FreeCAD's own parser).

mod support;

use support::root;

fn read(path: &str) -> String {
    std::fs::read_to_string(root().join(path)).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// The quoted value of `key = "..."` in the first section of a TOML file that has it.
fn toml_string(text: &str, key: &str) -> String {
    text.lines()
        .find_map(|line| {
            let (k, v) = line.split_once('=')?;
            (k.trim() == key).then(|| v.trim().trim_matches('"').to_string())
        })
        .unwrap_or_else(|| panic!("no {key} = \"...\""))
}

#[test]
fn the_packages_give_the_crates_addresses() {
    let cargo = read("Cargo.toml");
    let repository = toml_string(&cargo, "repository");
    let documentation = toml_string(&cargo, "documentation");
    assert!(repository.starts_with("https://") && documentation.starts_with("https://"));
    assert_eq!(
        toml_string(&read("capi/Cargo.toml"), "repository"),
        repository
    );

    let pyproject = read("python/pyproject.toml");
    let urls = &pyproject[pyproject.find("[project.urls]").expect("[project.urls]")..];
    assert_eq!(toml_string(urls, "Repository"), repository);
    assert_eq!(toml_string(urls, "Homepage"), repository);
    assert_eq!(toml_string(urls, "Documentation"), documentation);
    assert_eq!(toml_string(urls, "Issues"), format!("{repository}/issues"));

    let xml = read("freecad/package.xml");
    for element in [
        format!("branch=\"freecad-addon\">{repository}</url>"),
        format!("<url type=\"bugtracker\">{repository}/issues</url>"),
        format!("<url type=\"documentation\">{documentation}</url>"),
        format!("<url type=\"readme\">{repository}/blob/freecad-addon/README.md</url>"),
    ] {
        assert!(
            xml.contains(&element),
            "freecad/package.xml lacks {element}"
        );
    }
    for page in ["python/PACKAGE.md", "freecad/README.md"] {
        let text = read(page);
        assert!(
            text.contains(&documentation) && text.contains(&repository),
            "{page} does not give {documentation} and {repository}"
        );
    }
}

#[test]
fn the_license_expression_has_its_texts() {
    let expression = toml_string(&read("Cargo.toml"), "license");
    assert_eq!(expression, "MIT OR Apache-2.0");
    assert_eq!(
        toml_string(&read("python/pyproject.toml"), "license"),
        expression
    );
    let mit = read("LICENSE-MIT");
    let apache = read("LICENSE-APACHE");
    assert!(mit.starts_with("MIT License") && mit.contains("Permission is hereby granted"));
    assert!(apache.contains("Apache License") && apache.contains("Version 2.0, January 2004"));
    for link in ["python/LICENSE-MIT", "python/LICENSE-APACHE"] {
        let target =
            std::fs::read_link(root().join(link)).unwrap_or_else(|e| panic!("{link}: {e}"));
        assert_eq!(
            std::fs::read(root().join("python").join(target)).unwrap(),
            std::fs::read(root().join(&link["python/".len()..])).unwrap(),
            "{link}"
        );
    }
}
