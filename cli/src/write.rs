//! Writing the outputs all or nothing.
//!
//! Every destination is checked before the input is read ([`check`]): its directory
//! exists, it is not a directory or read-only, and no two destinations name the same file
//! (compared as canonical directory and file name, so `a.step` and `./a.step` are one
//! file). The rendered texts are then written to new files beside their destinations,
//! `.rmfsurf-<pid>-<n>.tmp` (created exclusively, so neither two runs nor two files of
//! one run share a name), and renamed into place one by one ([`write_all`]). A file that
//! was there is kept under a backup name until the run succeeds ([`Written::keep`]); when
//! any step fails, the files already renamed are taken back and the old ones restored
//! ([`Written::undo`]). Only a process killed outright (SIGKILL, a power cut) can leave a
//! `.rmfsurf-*` file behind.

use std::ffi::OsString;
use std::fmt::Display;
use std::fs::{self, File, OpenOptions};
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// A checked destination: the file `name` in the canonical directory `dir`.
#[derive(Debug)]
pub struct Target {
    /// The option that named it (`--output`, `--curves`), for messages.
    option: &'static str,
    /// The path as given, for messages.
    pub shown: PathBuf,
    dir: PathBuf,
    name: OsString,
}

impl Target {
    fn path(&self) -> PathBuf {
        self.dir.join(&self.name)
    }
}

fn cannot(shown: &Path, why: impl Display) -> String {
    format!("cannot write {}: {why}", shown.display())
}

/// Checks every destination (see the module notes); the error names the path.
pub fn check(destinations: Vec<(&'static str, PathBuf)>) -> Result<Vec<Target>, String> {
    let mut targets: Vec<Target> = Vec::with_capacity(destinations.len());
    for (option, shown) in destinations {
        let target = check_one(option, shown)?;
        if let Some(same) = targets
            .iter()
            .find(|t| t.dir == target.dir && t.name == target.name)
        {
            return Err(format!(
                "{} {} and {} {} are the same file: give each output once",
                same.option,
                same.shown.display(),
                target.option,
                target.shown.display()
            ));
        }
        targets.push(target);
    }
    Ok(targets)
}

fn check_one(option: &'static str, shown: PathBuf) -> Result<Target, String> {
    // `a.step/` and `a.step/.` name a directory although their file_name() is `a.step`.
    let last = shown
        .as_os_str()
        .as_encoded_bytes()
        .rsplit(|&b| b == b'/')
        .next()
        .unwrap_or_default();
    let name = match shown.file_name() {
        Some(name) if name.as_encoded_bytes() == last => name.to_owned(),
        _ => return Err(cannot(&shown, "the name is a directory's, not a file's")),
    };
    let parent = match shown.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    let dir = fs::canonicalize(parent).map_err(|e| cannot(&shown, e))?;
    if !dir.is_dir() {
        return Err(cannot(
            &shown,
            format!("{} is not a directory", parent.display()),
        ));
    }
    let target = Target {
        option,
        shown,
        dir,
        name,
    };
    match fs::metadata(target.path()) {
        Ok(m) if m.is_dir() => Err(cannot(&target.shown, "it is a directory")),
        Ok(m) if m.permissions().readonly() => Err(cannot(&target.shown, "the file is read-only")),
        Ok(_) => Ok(target),
        Err(e) if e.kind() == io::ErrorKind::NotFound => Ok(target),
        Err(e) => Err(cannot(&target.shown, e)),
    }
}

static COUNTER: AtomicU64 = AtomicU64::new(0);

/// Names tried for one new file before giving up (each taken name moves on to the next).
const ATTEMPTS: usize = 1000;

/// Makes a new entry `.rmfsurf-<pid>-<n>.<suffix>` in `dir` with `make`, which must fail
/// with `AlreadyExists` when the name is taken.
fn fresh<T>(
    dir: &Path,
    suffix: &str,
    mut make: impl FnMut(&Path) -> io::Result<T>,
) -> io::Result<(PathBuf, T)> {
    let mut attempt = 0;
    loop {
        let n = COUNTER.fetch_add(1, Ordering::Relaxed);
        let path = dir.join(format!(".rmfsurf-{}-{n}.{suffix}", std::process::id()));
        match make(&path) {
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists && attempt < ATTEMPTS => {
                attempt += 1
            }
            result => return result.map(|value| (path, value)),
        }
    }
}

fn create_new(path: &Path) -> io::Result<File> {
    OpenOptions::new().write(true).create_new(true).open(path)
}

/// Writes `text` to a new temporary file beside the target, with the permissions of the
/// file it replaces; the file's contents are on disk when this returns.
fn stage(target: &Target, text: &str) -> io::Result<PathBuf> {
    let (temp, mut file) = fresh(&target.dir, "tmp", create_new)?;
    let result = (|| {
        file.write_all(text.as_bytes())?;
        if let Ok(m) = fs::metadata(target.path()) {
            file.set_permissions(m.permissions())?;
        }
        // Some file systems report a full disk only here (or at close).
        file.sync_all()
    })();
    drop(file);
    match result {
        Ok(()) => Ok(temp),
        Err(e) => {
            let _ = fs::remove_file(&temp);
            Err(e)
        }
    }
}

/// Where the file a destination had is kept until the run ends.
#[derive(Debug)]
enum Backup {
    /// A second link to it: the destination stays in place until the rename replaces it.
    Linked(PathBuf),
    /// Moved away (where hard links are not possible).
    Moved(PathBuf),
}

impl Backup {
    fn path(&self) -> &Path {
        match self {
            Backup::Linked(p) | Backup::Moved(p) => p,
        }
    }
}

/// Keeps the file at `path`, if any, under a new name in `dir`.
fn back_up(dir: &Path, path: &Path) -> io::Result<Option<Backup>> {
    match fresh(dir, "bak", |backup| fs::hard_link(path, backup)) {
        Ok((backup, ())) => return Ok(Some(Backup::Linked(backup))),
        Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(None),
        Err(_) => {}
    }
    let (backup, file) = fresh(dir, "bak", create_new)?;
    drop(file);
    match fs::rename(path, &backup) {
        Ok(()) => Ok(Some(Backup::Moved(backup))),
        Err(e) => {
            let _ = fs::remove_file(&backup);
            if e.kind() == io::ErrorKind::NotFound {
                Ok(None)
            } else {
                Err(e)
            }
        }
    }
}

/// A destination replaced by its new file.
#[derive(Debug)]
struct Replaced {
    path: PathBuf,
    backup: Option<Backup>,
}

/// The files of a run, in place; what they replaced is kept until [`keep`](Self::keep) or
/// put back by [`undo`](Self::undo).
#[must_use = "keep the files or undo them"]
#[derive(Debug)]
pub struct Written {
    replaced: Vec<Replaced>,
}

impl Written {
    /// The run succeeded: drops the backups.
    pub fn keep(self) {
        for r in &self.replaced {
            if let Some(backup) = &r.backup {
                let _ = fs::remove_file(backup.path());
            }
        }
    }

    /// The run failed: removes the new files and puts back the old ones. The error lists
    /// the files that could not be put back.
    pub fn undo(self) -> Result<(), String> {
        let mut failed = Vec::new();
        for r in self.replaced.iter().rev() {
            let result = match &r.backup {
                Some(backup) => fs::rename(backup.path(), &r.path),
                None => fs::remove_file(&r.path),
            };
            if let Err(e) = result {
                failed.push(format!("{}: {e}", r.path.display()));
            }
        }
        if failed.is_empty() {
            Ok(())
        } else {
            Err(format!(
                "could not take back {} (the old file is kept as .rmfsurf-*.bak beside it)",
                failed.join(", ")
            ))
        }
    }
}

/// Renames `temp` to the target's path, keeping what was there.
fn replace(target: &Target, temp: &Path) -> io::Result<Replaced> {
    let path = target.path();
    let backup = back_up(&target.dir, &path)?;
    if let Err(e) = fs::rename(temp, &path) {
        match &backup {
            Some(Backup::Linked(b)) => drop(fs::remove_file(b)),
            Some(Backup::Moved(b)) => drop(fs::rename(b, &path)),
            None => {}
        }
        return Err(e);
    }
    Ok(Replaced { path, backup })
}

/// Writes every file or none (see the module notes); the error names the file at fault.
pub fn write_all(files: &[(Target, String)]) -> Result<Written, String> {
    let mut temps = Vec::with_capacity(files.len());
    for (target, text) in files {
        match stage(target, text) {
            Ok(temp) => temps.push(temp),
            Err(e) => {
                remove(&temps);
                return Err(cannot(&target.shown, e));
            }
        }
    }
    let mut written = Written {
        replaced: Vec::with_capacity(files.len()),
    };
    for (k, ((target, _), temp)) in files.iter().zip(&temps).enumerate() {
        match replace(target, temp) {
            Ok(replaced) => written.replaced.push(replaced),
            Err(e) => {
                remove(&temps[k..]);
                let message = cannot(&target.shown, e);
                return Err(match written.undo() {
                    Ok(()) => message,
                    Err(undo) => format!("{message}; {undo}"),
                });
            }
        }
    }
    Ok(written)
}

fn remove(paths: &[PathBuf]) {
    for p in paths {
        let _ = fs::remove_file(p);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("rmfsurf-write-{}-{name}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        dir
    }

    fn names(dir: &Path) -> Vec<String> {
        let mut names: Vec<String> = fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    }

    fn targets(dir: &Path, names: &[&str]) -> Result<Vec<Target>, String> {
        check(names.iter().map(|n| ("--output", dir.join(n))).collect())
    }

    #[test]
    fn checks_name_the_path_and_catch_two_spellings_of_one_file() {
        let dir = scratch("check");
        fs::create_dir(dir.join("sub.step")).unwrap();
        let e = targets(&dir, &["a.step", "sub.step"]).unwrap_err();
        assert!(e.ends_with("sub.step: it is a directory"), "{e}");
        let e = targets(&dir, &["a.step/"]).unwrap_err();
        assert!(e.contains("the name is a directory's"), "{e}");
        let e = targets(&dir, &["none/a.step"]).unwrap_err();
        assert!(e.contains("none/a.step: No such file"), "{e}");
        let e = targets(&dir, &["a.step", "./a.step"]).unwrap_err();
        assert!(e.contains("are the same file"), "{e}");
        let e = targets(&dir, &["a.step", "sub.step/../a.step"]).unwrap_err();
        assert!(e.contains("are the same file"), "{e}");
        assert_eq!(names(&dir), ["sub.step"]);
        fs::remove_dir_all(&dir).unwrap();
    }

    /// A rename that fails after others succeeded (here: the destination became a
    /// directory after the check) takes the new files back and restores the old one.
    #[test]
    fn a_failed_rename_undoes_the_others() {
        let dir = scratch("undo");
        fs::write(dir.join("old.step"), "old").unwrap();
        let checked = targets(&dir, &["new.step", "old.step", "late.step"]).unwrap();
        fs::create_dir(dir.join("late.step")).unwrap();
        fs::write(dir.join("late.step/x"), "").unwrap();
        let files: Vec<(Target, String)> = checked.into_iter().map(|t| (t, "new".into())).collect();
        let e = write_all(&files).unwrap_err();
        assert!(
            e.starts_with(&format!("cannot write {}", dir.join("late.step").display())),
            "{e}"
        );
        assert_eq!(names(&dir), ["late.step", "old.step"]);
        assert_eq!(fs::read_to_string(dir.join("old.step")).unwrap(), "old");
        // Undoing a run that succeeded restores the old file too; keeping drops the backup.
        fs::remove_dir_all(dir.join("late.step")).unwrap();
        let written = write_all(&files).unwrap();
        assert_eq!(fs::read_to_string(dir.join("old.step")).unwrap(), "new");
        written.undo().unwrap();
        assert_eq!(names(&dir), ["old.step"]);
        assert_eq!(fs::read_to_string(dir.join("old.step")).unwrap(), "old");
        write_all(&files).unwrap().keep();
        assert_eq!(names(&dir), ["late.step", "new.step", "old.step"]);
        fs::remove_dir_all(&dir).unwrap();
    }
}
