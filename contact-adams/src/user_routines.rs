//! User force routines (NORMAL_ROUTINE, FRICTION_ROUTINE): where a CONTACT's
//! `library::function` comes from.
//!
//! A routine is looked up first among the laws registered in code ([`UserRoutines::register_normal`],
//! [`UserRoutines::register_friction`], under the exact `library::function` text the dataset
//! gives), then in a shared library through the C ABI documented in
//! [`contact_core::laws::UserContactAbi`] (`examples/user_routines/contact_user.h` is the
//! header; `examples/user_routines/impact_routine.rs` an example routine).
//!
//! The library part names a file. A name with a path separator or an extension is a path,
//! taken relative to the directory of the dataset that names it; a bare name `NAME` is the
//! platform's file name for it (`libNAME.so`, `libNAME.dylib`, `NAME.dll`), looked for in the
//! dataset's directory and then by the system's loader (its search path). A library that
//! cannot be loaded or lacks the function is an error naming what was tried, before the run.
//!
//! # Safety of shared libraries
//!
//! Loading a library runs its initialisers, and calling a routine trusts it to have the
//! documented signature, to read only the input it is given, to write only its outputs and to
//! be callable from several threads at once. Nothing can check that from outside: naming a
//! library in a dataset is trusting it, as in Adams. The unsafe code is confined to this file.
#![allow(unsafe_code)]

use contact_core::laws::{
    UserContact, UserContactAbi, UserFriction, UserFrictionLaw, UserLawError, UserNormalLaw,
};
use contact_core::{UserRoutine, Vector3};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

pub use contact_solver::contact_force::UserLaws;

/// The signature of a routine in a shared library.
type RawRoutine = unsafe extern "C" fn(*const UserContactAbi, *mut f64) -> i32;

/// Why a routine could not be found.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum UserRoutineError {
    /// No library file of that name could be loaded.
    #[error("{routine}: cannot load the library {library:?} (tried {tried}): {reason}")]
    Library {
        /// `library::function`.
        routine: String,
        /// The library as written.
        library: String,
        /// The files and names tried, in order.
        tried: String,
        /// The loader's message for the last one.
        reason: String,
    },
    /// The library has no such function.
    #[error("{routine}: the library {path} has no function {function:?}: {reason}")]
    Symbol {
        /// `library::function`.
        routine: String,
        /// The library file loaded.
        path: String,
        /// The function.
        function: String,
        /// The loader's message.
        reason: String,
    },
}

/// Where user routines come from: laws registered in code, then shared libraries.
#[derive(Clone, Default)]
pub struct UserRoutines {
    normal: BTreeMap<String, Arc<dyn UserNormalLaw>>,
    friction: BTreeMap<String, Arc<dyn UserFrictionLaw>>,
}

impl std::fmt::Debug for UserRoutines {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("UserRoutines")
            .field("normal", &self.normal.keys().collect::<Vec<_>>())
            .field("friction", &self.friction.keys().collect::<Vec<_>>())
            .finish()
    }
}

impl UserRoutines {
    /// Registers a normal force law under `routine` (`library::function`, as the dataset
    /// writes it; matched exactly).
    pub fn register_normal(
        &mut self,
        routine: impl Into<String>,
        law: impl UserNormalLaw + 'static,
    ) -> &mut Self {
        self.normal.insert(routine.into(), Arc::new(law));
        self
    }

    /// Registers a friction law under `routine` (`library::function`; matched exactly).
    pub fn register_friction(
        &mut self,
        routine: impl Into<String>,
        law: impl UserFrictionLaw + 'static,
    ) -> &mut Self {
        self.friction.insert(routine.into(), Arc::new(law));
        self
    }

    /// The normal law of `routine`: registered, else loaded from its library, with the
    /// library's relative path taken from `dataset_dir`.
    pub fn normal(
        &self,
        routine: &UserRoutine,
        dataset_dir: &Path,
    ) -> Result<Arc<dyn UserNormalLaw>, UserRoutineError> {
        if let Some(law) = self.normal.get(&name(routine)) {
            return Ok(law.clone());
        }
        Ok(Arc::new(SharedRoutine::load(routine, dataset_dir, 1)?))
    }

    /// The friction law of `routine`: registered, else loaded from its library.
    pub fn friction(
        &self,
        routine: &UserRoutine,
        dataset_dir: &Path,
    ) -> Result<Arc<dyn UserFrictionLaw>, UserRoutineError> {
        if let Some(law) = self.friction.get(&name(routine)) {
            return Ok(law.clone());
        }
        Ok(Arc::new(SharedRoutine::load(routine, dataset_dir, 4)?))
    }
}

fn name(routine: &UserRoutine) -> String {
    format!("{}::{}", routine.library, routine.function)
}

/// The files to try for a library named `library` by a dataset in `dataset_dir`, in order.
pub fn library_candidates(library: &str, dataset_dir: &Path) -> Vec<PathBuf> {
    let as_path = Path::new(library);
    let is_path = library.contains(['/', '\\']) || as_path.extension().is_some();
    if is_path {
        return vec![if as_path.is_absolute() {
            as_path.to_path_buf()
        } else {
            dataset_dir.join(as_path)
        }];
    }
    let file = format!(
        "{}{library}{}",
        std::env::consts::DLL_PREFIX,
        std::env::consts::DLL_SUFFIX
    );
    // The second is a bare file name: the system loader searches its own path for it.
    vec![dataset_dir.join(&file), PathBuf::from(file)]
}

/// A routine in a loaded shared library; the library stays loaded while the routine lives.
struct SharedRoutine {
    function: RawRoutine,
    outputs: usize,
    _library: Arc<libloading::Library>,
}

impl SharedRoutine {
    fn load(
        routine: &UserRoutine,
        dataset_dir: &Path,
        outputs: usize,
    ) -> Result<Self, UserRoutineError> {
        let candidates = library_candidates(&routine.library, dataset_dir);
        let mut reason = String::new();
        let mut loaded = None;
        for candidate in &candidates {
            // SAFETY: loading a library the dataset names runs its initialisers; naming it is
            // trusting it (module docs).
            match unsafe { libloading::Library::new(candidate) } {
                Ok(library) => {
                    loaded = Some((candidate, library));
                    break;
                }
                Err(e) => reason = e.to_string(),
            }
        }
        let Some((path, library)) = loaded else {
            return Err(UserRoutineError::Library {
                routine: name(routine),
                library: routine.library.clone(),
                tried: candidates
                    .iter()
                    .map(|c| c.display().to_string())
                    .collect::<Vec<_>>()
                    .join(", "),
                reason,
            });
        };
        // SAFETY: the symbol is taken to have the documented signature (module docs); the
        // function pointer is kept only together with the library that holds it.
        let function = unsafe { library.get::<RawRoutine>(routine.function.as_bytes()) }
            .map(|symbol| *symbol)
            .map_err(|e| UserRoutineError::Symbol {
                routine: name(routine),
                path: path.display().to_string(),
                function: routine.function.clone(),
                reason: e.to_string(),
            })?;
        Ok(Self {
            function,
            outputs,
            _library: Arc::new(library),
        })
    }

    fn call(&self, contact: &UserContact<'_>) -> Result<[f64; 4], UserLawError> {
        let input = UserContactAbi::new(contact);
        let mut output = [f64::NAN; 4];
        debug_assert!(self.outputs <= output.len());
        // SAFETY: `input` and `output` outlive the call; the routine writes at most `outputs`
        // doubles (the ABI: 1 for a normal routine, 4 for a friction routine).
        let code = unsafe { (self.function)(&input, output.as_mut_ptr()) };
        if code != 0 {
            return Err(UserLawError::Code(code));
        }
        Ok(output)
    }
}

impl UserNormalLaw for SharedRoutine {
    fn normal_force(&self, contact: &UserContact<'_>) -> Result<f64, UserLawError> {
        self.call(contact).map(|out| out[0])
    }
}

impl UserFrictionLaw for SharedRoutine {
    fn friction(&self, contact: &UserContact<'_>) -> Result<UserFriction, UserLawError> {
        self.call(contact).map(|out| UserFriction {
            force_w: Vector3::new(out[0], out[1], out[2]),
            torque: out[3],
        })
    }
}
