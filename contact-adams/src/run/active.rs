//! ACTIVATE and DEACTIVATE: the elements a command file has switched off, the model without
//! them, and the output frames of that model laid out as the whole model's.
//!
//! As in Adams, a deactivated element disappears from the model for the analyses that follow
//! (until an ACTIVATE brings it back): a deactivated JOINT no longer constrains its parts,
//! which move on freely from the state they reached; a deactivated SFORCE or CONTACT applies
//! no force. The model is lowered again without the inactive elements, starting from the part
//! states the previous analysis reached, and its initial conditions (assembly, consistent
//! velocities, multipliers) are found anew as at the start of any analysis.

use crate::model::{Model, MotionTarget};
use contact_solver::frame::{ElementReaction, FrameDynamics};
use contact_solver::simulate::Frame;
use std::collections::BTreeSet;

/// The element classes ACTIVATE and DEACTIVATE apply to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum ElementClass {
    /// JOINT.
    Joint,
    /// JPRIM.
    Jprim,
    /// GCON.
    Gcon,
    /// MOTION.
    Motion,
    /// SFORCE.
    Sforce,
    /// CONTACT.
    Contact,
}

impl ElementClass {
    /// Every class that can be switched, in the order they are listed in messages.
    pub const ALL: [Self; 6] = [
        Self::Joint,
        Self::Jprim,
        Self::Gcon,
        Self::Motion,
        Self::Sforce,
        Self::Contact,
    ];

    /// The class of an ACTIVATE/DEACTIVATE keyword (`JOINT`, …), `None` for a class that
    /// cannot be switched here.
    pub fn from_keyword(keyword: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|c| c.keyword() == keyword)
    }

    /// The statement keyword.
    pub fn keyword(self) -> &'static str {
        match self {
            Self::Joint => "JOINT",
            Self::Jprim => "JPRIM",
            Self::Gcon => "GCON",
            Self::Motion => "MOTION",
            Self::Sforce => "SFORCE",
            Self::Contact => "CONTACT",
        }
    }

    /// Whether `model` has the element `id` of this class.
    pub fn exists(self, model: &Model, id: u32) -> bool {
        match self {
            Self::Joint => model.joints.iter().any(|e| e.id == id),
            Self::Jprim => model.primitives.iter().any(|e| e.id == id),
            Self::Gcon => model.gcons.iter().any(|e| e.id == id),
            Self::Motion => model.motions.iter().any(|e| e.id == id),
            Self::Sforce => model.sforces.iter().any(|e| e.id == id),
            Self::Contact => model.contacts.iter().any(|e| e.id == id),
        }
    }

    /// The ids of this class's elements in `model`, ascending.
    pub fn ids_of(self, model: &Model) -> Vec<u32> {
        let mut ids: Vec<u32> = match self {
            Self::Joint => model.joints.iter().map(|e| e.id).collect(),
            Self::Jprim => model.primitives.iter().map(|e| e.id).collect(),
            Self::Gcon => model.gcons.iter().map(|e| e.id).collect(),
            Self::Motion => model.motions.iter().map(|e| e.id).collect(),
            Self::Sforce => model.sforces.iter().map(|e| e.id).collect(),
            Self::Contact => model.contacts.iter().map(|e| e.id).collect(),
        };
        ids.sort_unstable();
        ids
    }

    /// The keywords of every class that can be switched, comma-separated.
    pub fn list() -> String {
        Self::ALL.map(Self::keyword).join(", ")
    }
}

/// The elements switched off (by DEACTIVATE, not yet brought back by ACTIVATE).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Inactive(BTreeSet<(ElementClass, u32)>);

impl Inactive {
    /// No element is switched off.
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    /// Whether element `id` of `class` is switched off.
    pub fn contains(&self, class: ElementClass, id: u32) -> bool {
        self.0.contains(&(class, id))
    }

    /// Switches element `id` of `class` on (`active`) or off; true when that changed it.
    pub fn set(&mut self, class: ElementClass, id: u32, active: bool) -> bool {
        if active {
            self.0.remove(&(class, id))
        } else {
            self.0.insert((class, id))
        }
    }

    /// The ids of the switched-off elements of `class`, in order.
    pub fn ids(&self, class: ElementClass) -> impl Iterator<Item = u32> + '_ {
        self.0
            .iter()
            .filter(move |(c, _)| *c == class)
            .map(|(_, id)| *id)
    }

    /// The switched-off elements as `JOINT/1, SFORCE/3`.
    pub fn names(&self) -> String {
        let names: Vec<String> = self
            .0
            .iter()
            .map(|(c, id)| format!("{}/{id}", c.keyword()))
            .collect();
        names.join(", ")
    }

    /// Applies one ACTIVATE (`active`) or DEACTIVATE of `ids` of `class`, from `time` on;
    /// what it did, in words.
    pub fn switch(&mut self, active: bool, class: &str, ids: &[u32], time: f64) -> String {
        // The dataset reader accepts only the classes that can be switched.
        let Some(class) = ElementClass::from_keyword(class) else {
            return format!("{class} elements cannot be switched: the command is ignored");
        };
        let (changed, unchanged): (Vec<u32>, Vec<u32>) =
            ids.iter().partition(|&&id| self.set(class, id, active));
        let names = |ids: &[u32]| {
            let names: Vec<String> = ids
                .iter()
                .map(|id| format!("{}/{id}", class.keyword()))
                .collect();
            names.join(", ")
        };
        let mut parts = Vec::new();
        if !changed.is_empty() {
            parts.push(if active {
                format!(
                    "{} back in the model from t = {time:?} (the next analysis)",
                    names(&changed)
                )
            } else {
                format!(
                    "{} removed from the model from t = {time:?} (the next analysis) until ACTIVATE",
                    names(&changed)
                )
            });
        }
        if !unchanged.is_empty() {
            parts.push(format!(
                "{} already {}: no change",
                names(&unchanged),
                if active { "active" } else { "deactivated" }
            ));
        }
        parts.join("; ")
    }

    /// An active MOTION on a switched-off JOINT, as `(motion, joint)`: the motion has nothing
    /// to drive.
    pub fn orphan_motion(&self, model: &Model) -> Option<(u32, u32)> {
        model.motions.iter().find_map(|m| match m.target {
            MotionTarget::Joint { joint, .. }
                if !self.contains(ElementClass::Motion, m.id)
                    && self.contains(ElementClass::Joint, joint) =>
            {
                Some((m.id, joint))
            }
            _ => None,
        })
    }

    /// `model` without the switched-off elements.
    pub fn apply(&self, model: &Model) -> Model {
        let mut out = model.clone();
        let on = |class: ElementClass| move |id: u32| !self.contains(class, id);
        out.joints.retain(|e| on(ElementClass::Joint)(e.id));
        out.primitives.retain(|e| on(ElementClass::Jprim)(e.id));
        out.gcons.retain(|e| on(ElementClass::Gcon)(e.id));
        out.motions.retain(|e| on(ElementClass::Motion)(e.id));
        out.sforces.retain(|e| on(ElementClass::Sforce)(e.id));
        out.contacts.retain(|e| on(ElementClass::Contact)(e.id));
        out
    }
}

/// Where the output of a model with elements switched off goes in the whole model's layout:
/// each CONTACT's reports at its place among all the model's CONTACTs (none while it is
/// off), each constraint's reaction at its place among all the constraints (zero while off).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FrameMap {
    /// Per CONTACT of the whole model, its index in the frame (`None`: switched off).
    contacts: Vec<Option<usize>>,
    /// Per constraint of the whole model, its index in the frame's reactions.
    reactions: Vec<Option<usize>>,
}

impl FrameMap {
    /// The map from a model lowered without `inactive` (its constraints named `current`, in
    /// row order) to `model` whole (its constraints named `whole`); `None` when nothing is
    /// switched off (the layouts are the same).
    pub fn new<'a>(
        model: &Model,
        inactive: &Inactive,
        whole: impl Iterator<Item = &'a str>,
        current: &[&str],
    ) -> Option<Self> {
        if inactive.is_empty() {
            return None;
        }
        let mut k = 0;
        let contacts = model
            .contacts
            .iter()
            .map(|c| {
                (!inactive.contains(ElementClass::Contact, c.id)).then(|| {
                    k += 1;
                    k - 1
                })
            })
            .collect();
        let reactions = whole
            .map(|name| current.iter().position(|n| *n == name))
            .collect();
        Some(Self {
            contacts,
            reactions,
        })
    }

    /// `frame` in the whole model's layout.
    pub fn remap(&self, frame: &Frame) -> Frame {
        let contacts = self
            .contacts
            .iter()
            .map(|k| k.map_or_else(Vec::new, |k| frame.contacts[k].clone()))
            .collect();
        let dynamics = frame.dynamics.as_ref().map(|d| FrameDynamics {
            accelerations: d.accelerations.clone(),
            reactions: self
                .reactions
                .iter()
                .map(|k| k.map_or_else(ElementReaction::default, |k| d.reactions[k]))
                .collect(),
        });
        Frame {
            t: frame.t,
            parts: frame.parts.clone(),
            contacts,
            dynamics,
        }
    }
}
