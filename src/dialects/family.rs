//! The contract a controller family fulfils: what its file provides, and nothing it may
//! reach for beyond the text room and the mathematics.
//!
//! A family (SINUMERIK, Heidenhain, Fanuc, …) is one file or folder under `src/dialects/`
//! with a unit struct that implements [`Family`]: the longest block it reads, the commands
//! whose frames it computes ([`FormInfo`]), its block reader, the names of the forms its
//! writer takes and its writer, and the frame ↔ words functions of its forms. The one list
//! of families is the `families!` invocation in `registry.rs`: a new controller is its own
//! file plus one line there. Families import this module, `crate::text` and the
//! mathematics, and other families' public commands where a controller reads another's
//! (Syntec reads Fanuc's `G68.2`) — never the registry, `program.rs` or `form.rs`, which
//! dispatch to them.

use crate::text::number::Out;
use crate::text::scan::LineError;
use crate::{Axis, Error, Frame, Vector};

/// The most words a form has.
pub const MAX_VALUES: usize = 9;

/// What the blocks read so far leave active, in the terms every family shares: the frame,
/// TwinCAT's programmed angles (its `AROT` adds angles, not matrices), SINUMERIK's angle
/// mode (machine data, not a block), the datum shift a program made active and the
/// solution the active tilt's own words choose for the rotary axes.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Modal {
    /// The active frame (identity: nothing active): the datum shift, then the tilt.
    pub frame: Frame,
    /// TwinCAT's programmed angles `X Y Z`; a direct mode's rotary-axis positions.
    pub angles: [f64; 3],
    /// SINUMERIK's frame angles in Euler mode (machine data 10600 = 2) instead of RPY.
    pub euler: bool,
    /// Heidenhain's `CYCL DEF 19` angles as the rotary axes' positions (a direct mode)
    /// instead of spatial angles (machine parameter, iTNC 530 MP7500 bit 1 = 0).
    pub axis_angles: bool,
    /// The datum shift the program made active (`CYCL DEF 7`, `TRANS DATUM`, `G52`), in
    /// the workpiece axes before the tilt: part of `frame`'s origin, kept when a tilt is
    /// cancelled.
    pub shift: Vector,
    /// The solution the active tilt's own words choose (`SEQ±`, `_DIR`, `G53.1 P`).
    pub choice: AxisChoice,
    /// How the program moves the machine to the active tilt (`TURN`, `G53.1`, …).
    pub positioning: Positioning,
    /// How the tool retracts before the axes turn (`MB`, `_FR`).
    pub retract: Retract,
    /// The retraction's length in mm for [`Retract::Tool`], else 0.
    pub retract_mm: f64,
    /// How fast the axes turn (`FMAX`, `F`).
    pub feed: Feed,
    /// The feed rate in mm/min for [`Feed::Rate`], else 0.
    pub feed_mm_min: f64,
    /// An active direct mode (`PLANE AXIAL`, `CYCLE800` direct, `G158` mode 2), its
    /// positions in `angles`: the rotation follows from the machine, so `frame` holds only
    /// the origin (its rotation the identity).
    pub direct: Option<Direct>,
    /// The working plane (`G17`–`G19`).
    pub plane: Plane,
    /// The active tilt turns a free rotary table to the plane (Heidenhain `TABLE ROT`).
    pub table_rot: bool,
    /// The active tilt was set by a block that adds to the tilt before it (`PLANE RELATIV`,
    /// `G68.4`, `AROT`, …).
    pub relative: bool,
}

/// A direct mode: a block that states rotary-axis positions (`PLANE AXIAL B+30 C+45`, a
/// `CYCLE800` with `_MODE` 192, `G158 P10200 … A B C`), kept in the state's `angles`
/// (degrees; 0 where not given): the plane is where the machine's kinematics puts it with
/// its rotary axes there, so the frame needs the machine
/// ([`crate::dialects::program::Program::frame_on`]). The positions live beside it, not in
/// it, as in the C state (and a state is copied often while a block is read: stack bound).
///
/// ```
/// use cncrot::dialects::program::{Dialect, Direct, DirectAxes, Program};
/// let (p, _) = Program::default().line(Dialect::Heidenhain, b"PLANE AXIAL B+30 C+45 TURN").unwrap();
/// assert_eq!(p.direct, Some(Direct { by: DirectAxes::Letters, given: 0b110 }));
/// assert_eq!(p.angles, [0.0, 30.0, 45.0]);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Direct {
    /// How the positions name their axes.
    pub by: DirectAxes,
    /// Which positions the block gave: bit k for `angles[k]`.
    pub given: u8,
}

/// How a direct mode names the rotary axes it positions.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DirectAxes {
    /// By address letter: A about X, B about Y, C about Z (Heidenhain `PLANE AXIAL`,
    /// Syntec `G158` mode 2). On a machine, an axis takes the letter of the machine axis
    /// its direction is nearest \[choice: the machine's axis names are not part of its
    /// description\].
    Letters,
    /// By place in the machine's kinematics: rotary axis 1, 2, 3 (a `CYCLE800` direct:
    /// `_A` the swivel data set's first axis, `_B` its second).
    Numbered,
}

/// The working plane a program selected (`G17`, `G18`, `G19`): the plane of the rotations
/// that name no axis (SINUMERIK `ROT RPL=`, Fanuc-style `G68 X Y R`), which turn about its
/// normal. `G17` is the default \[choice: the power-on setting of milling machines; a
/// program that needs another selects it\].
///
/// ```
/// use cncrot::dialects::program::{Dialect, Plane, Program};
/// let (p, _) = Program::default().line(Dialect::Fanuc, b"G18 G90").unwrap();
/// assert_eq!(p.plane, Plane::Zx);
/// assert_eq!(p.plane.normal(), cncrot::Axis::Y);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Plane {
    /// `G17`: X and Y, rotations about Z.
    #[default]
    Xy,
    /// `G18`: Z and X, rotations about Y.
    Zx,
    /// `G19`: Y and Z, rotations about X.
    Yz,
}

impl Plane {
    /// The axis the plane's rotations turn about (a positive angle turns its first axis
    /// toward its second: X to Y, Z to X, Y to Z).
    pub fn normal(self) -> Axis {
        match self {
            Plane::Xy => Axis::Z,
            Plane::Zx => Axis::Y,
            Plane::Yz => Axis::X,
        }
    }

    /// The plane a G-code selects (its code in tenths: `G17` is 170), if it selects one.
    pub(crate) fn of_code(code: u32) -> Option<Plane> {
        match code {
            170 => Some(Plane::Xy),
            180 => Some(Plane::Zx),
            190 => Some(Plane::Yz),
            _ => None,
        }
    }

    /// The indices (0 X, 1 Y, 2 Z) of the plane's first and second axes (whose words give
    /// the centre of a rotation in it) and of its normal.
    pub(crate) fn axes(self) -> [usize; 3] {
        match self {
            Plane::Xy => [0, 1, 2],
            Plane::Zx => [2, 0, 1],
            Plane::Yz => [1, 2, 0],
        }
    }
}

/// How a program moves the machine to its tilted plane, as its blocks say: Heidenhain's
/// `STAY`, `TURN`, `MOVE`; Fanuc-style `G53.1` and `G53.6` after a `G68.2`; Haas `G253`.
///
/// ```
/// use cncrot::dialects::program::Positioning;
/// assert_eq!(Positioning::default(), Positioning::Stay);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Positioning {
    /// The tilt command moves no axis (`STAY`; a `G68.2`, `G268` without `G53.1`, `G253`;
    /// frames): the rotary axes are positioned by later blocks.
    #[default]
    Stay,
    /// The rotary axes turn to the plane, the linear axes stay (`TURN`, `G53.1`, `G253`;
    /// `CYCLE800`, which swivels).
    Turn,
    /// The rotary axes turn and the linear axes follow so that the tool tip keeps its place
    /// (`MOVE`, `G53.6`).
    Move,
}

/// The solution a block's own words choose for the rotary axes, where a tilt has two:
/// Heidenhain `SEQ+`/`SEQ-`, SINUMERIK `CYCLE800` `_DIR` +1/−1 (a side of an axis), the
/// `P` of a Fanuc-style `G53.1`/`G53.6` (a direction of travel).
///
/// ```
/// use cncrot::dialects::program::AxisChoice;
/// assert_eq!(AxisChoice::default(), AxisChoice::Closest);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum AxisChoice {
    /// No words: the dialect's default, the solution closest to the current positions.
    #[default]
    Closest,
    /// The lower angle (in (−180°, 180°]) of an axis: 1..=3 in chain order, or 0 for the
    /// machine's master axis (for a head the axis nearest the tool, else the axis nearest
    /// the machine base).
    Minus(u8),
    /// The higher angle of an axis (numbered as for `Minus`).
    Plus(u8),
    /// The axis turns only in its positive direction, the least it must (`G53.1 P1`
    /// \[3rd: LinuxCNC's tilted-work-plane remap, "positive rotation only" of the primary
    /// axis\]; numbered as for `Minus`).
    PositiveTurn(u8),
    /// The axis turns only in its negative direction (`G53.1 P2`).
    NegativeTurn(u8),
}

/// The tilt of `frame` without the datum shift `shift` before it.
pub(crate) fn tilt_of(frame: &Frame, shift: Vector) -> Frame {
    let t = frame.translation;
    Frame {
        rotation: frame.rotation,
        translation: [t[0] - shift[0], t[1] - shift[1], t[2] - shift[2]],
    }
}

/// How the tool retracts before the rotary axes turn to a plane, as the tilt block says:
/// Heidenhain's `MB` in a `PLANE`, SINUMERIK's `_FR` (with `_FR_I`) in a `CYCLE800`. The
/// other dialects retract in blocks of their own (`G53 Z…`, `G28`), not in the tilt.
///
/// ```
/// use cncrot::dialects::program::{Dialect, Program, Retract};
/// let (p, _) = Program::default()
///     .line(Dialect::Heidenhain, b"PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN MB50 FMAX")
///     .unwrap();
/// assert_eq!((p.retract, p.retract_mm), (Retract::Tool, 50.0));
/// ```
///
/// The length of [`Retract::Tool`] is kept beside it (`retract_mm`), as in the C state: a
/// state is copied often while a block is read (stack bound).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Retract {
    /// No retraction (no `MB`, `MB0`; `_FR` 0).
    #[default]
    None,
    /// As far as the travel allows along the tool axis (`MB MAX`: "just before the software
    /// limit switch" \[doc\]; `_FR` 4, "maximum retraction in tool direction" \[choice:
    /// the dialog's mode, its number from the order of the modes\]).
    ToolMax,
    /// A length (`retract_mm`) along the tool axis, incrementally (`MB n` \[doc\]; `_FR` 5
    /// with `_FR_I` = n, "incremental retraction in tool direction" \[choice, as
    /// `ToolMax`\]).
    Tool,
    /// Along the machine's Z axis (`_FR` 1 \[3rd: CAM posts\]).
    MachineZ,
    /// Along the machine's Z axis, then in X and Y (`_FR` 2 \[3rd: CAM posts\]).
    MachineZThenXy,
}

/// How fast the rotary axes turn to a plane, as a Heidenhain `PLANE` says it: at rapid
/// (`FMAX`, and every dialect without a feed word in its tilt), at a feed rate (`F n`,
/// mm/min), or at the feed programmed before (`F AUTO` \[choice: the manuals' wording not
/// found\]).
///
/// ```
/// use cncrot::dialects::program::{Dialect, Feed, Program};
/// let (p, _) = Program::default()
///     .line(Dialect::Heidenhain, b"PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN F2000")
///     .unwrap();
/// assert_eq!((p.feed, p.feed_mm_min), (Feed::Rate, 2000.0));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Feed {
    /// At rapid.
    #[default]
    Rapid,
    /// At a feed rate (`feed_mm_min`).
    Rate,
    /// At the feed rate programmed before (`F AUTO`).
    Auto,
}

impl Modal {
    /// This state with `tilt` active after the datum shift (TwinCAT's angles cleared: they
    /// belong to `ROT`; the choice and positioning words cleared: a tilt states its own).
    pub fn with_frame(&self, tilt: Frame) -> Modal {
        let t = tilt.translation;
        let s = self.shift;
        Modal {
            frame: Frame {
                rotation: tilt.rotation,
                translation: [s[0] + t[0], s[1] + t[1], s[2] + t[2]],
            },
            angles: [0.0; 3],
            choice: AxisChoice::Closest,
            positioning: Positioning::Stay,
            retract: Retract::None,
            retract_mm: 0.0,
            feed: Feed::Rapid,
            feed_mm_min: 0.0,
            direct: None,
            table_rot: false,
            relative: false,
            ..*self
        }
    }

    /// [`Modal::with_frame`] for a command that adds to the active tilt where `added` (its
    /// frame the active one composed with the command's): the state remembers it, so that
    /// a translator writes the target's incremental form.
    pub fn with_tilt(&self, tilt: Frame, added: bool) -> Modal {
        Modal {
            relative: added,
            ..self.with_frame(tilt)
        }
    }

    /// This state with the direct mode `direct` active at `positions`, its origin `origin`
    /// after the datum shift (the choice and positioning words cleared, as by
    /// [`Modal::with_frame`]).
    pub fn with_direct(&self, origin: Vector, direct: Direct, positions: [f64; 3]) -> Modal {
        Modal {
            direct: Some(direct),
            angles: positions.map(|x| x + 0.0),
            ..self.with_frame(Frame::with_translations(origin, crate::IDENTITY, [0.0; 3]))
        }
    }

    /// The active tilt as the base of an incremental command (`PLANE RELATIV`, `G68.4`,
    /// `AROT`, an additive `CYCLE800`): [`Error::NotAvailable`] while a direct mode is
    /// active, whose rotation only the machine knows.
    pub fn tilt_base(&self) -> Result<Frame, Error> {
        match self.direct {
            Some(_) => Err(Error::NotAvailable),
            None => Ok(self.tilt()),
        }
    }

    /// The tilt alone: the frame without the datum shift before it.
    pub fn tilt(&self) -> Frame {
        tilt_of(&self.frame, self.shift)
    }

    /// This state with the datum shift `shift` instead of the one active (the tilt kept).
    pub fn with_shift(&self, shift: Vector) -> Modal {
        let tilt = self.tilt();
        let t = tilt.translation;
        let frame = if tilt == Frame::IDENTITY && shift == [0.0; 3] {
            Frame::IDENTITY
        } else {
            Frame {
                rotation: tilt.rotation,
                translation: [shift[0] + t[0], shift[1] + t[1], shift[2] + t[2]],
            }
        };
        Modal {
            frame,
            shift: shift.map(|x| x + 0.0),
            ..*self
        }
    }
}

/// What one block of a program does, as its family's reader sees it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Block {
    /// A command the family reads, and the state it leaves (possibly the same: `G53.1`).
    Frame(Modal),
    /// Nothing to do with the frame: motion, tool, M and S words, program structure,
    /// labels and calls, parameter assignments, comments, a blank line.
    Passed,
    /// A change of the frame the library does not follow: a work-offset, preset or datum
    /// table selection, a write to such a table or to a frame variable, mirroring, scaling,
    /// a plane rotation of its own, a tilt that needs the machine. The state stays as it
    /// was and may no longer be the control's.
    NotFollowed,
}

/// A tilted-plane command as written, with the order of its words. The codes are the C
/// boundary's `CNCROT_FORM_*` (an ABI list: a family that brings a new command adds its
/// code here, numbered by hand).
///
/// | form | selector | words, in this order |
/// |---|---|---|
/// | [`Form::Cycle800`] | `_MODE` | `_X0 _Y0 _Z0 _A _B _C _X1 _Y1 _Z1` |
/// | [`Form::SinumerikRot`] | 0 RPY, 1 Euler | `X Y Z` |
/// | [`Form::SinumerikRots`] | 0 `X Y`, 1 `Y Z`, 2 `Z X` | the two angles in that order |
/// | [`Form::PlaneSpatial`] | 0 | `SPA SPB SPC` |
/// | [`Form::PlaneEuler`] | 0 | `EULPR EULNU EULROT` |
/// | [`Form::PlaneVector`] | 0 | `BX BY BZ NX NY NZ` |
/// | [`Form::PlanePoints`] | 0 | `P1X P1Y P1Z P2X P2Y P2Z P3X P3Y P3Z` |
/// | [`Form::G68_2`] | 0 | `X Y Z I J K` |
/// | [`Form::G158`] | `P` | `X Y Z A B C U V W` |
/// | [`Form::TwincatRot`] | 0 | `X Y Z` |
/// | [`Form::G268`] | `Q` | `X Y Z I J K` |
/// | [`Form::G68_3`] | 0 | `X Y Z R TX TY TZ` (the tool direction T; vertical axis +Z) |
/// | [`Form::PlaneProjected`] | 0 | `PROPR PROMIN PROROT` |
///
/// ```
/// use cncrot::dialects::form::{form_frame, Form};
/// // G68.2 X10 I0 J30 K0: origin (10, 0, 0), tilted about X by 30°.
/// let f = form_frame(Form::G68_2, 0, &[10.0, 0.0, 0.0, 0.0, 30.0, 0.0]).unwrap();
/// assert_eq!(f.translation, [10.0, 0.0, 0.0]);
/// assert_eq!((Form::G68_2.count(), Form::G68_2.has_origin()), (6, true));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Form {
    /// SINUMERIK `CYCLE800`.
    Cycle800 = 1,
    /// SINUMERIK `ROT`/`CROT` (and each step of `AROT`).
    SinumerikRot = 2,
    /// SINUMERIK `ROTS` (projection angles).
    SinumerikRots = 3,
    /// Heidenhain `PLANE SPATIAL`.
    PlaneSpatial = 4,
    /// Heidenhain `PLANE EULER`.
    PlaneEuler = 5,
    /// Heidenhain `PLANE VECTOR`.
    PlaneVector = 6,
    /// Heidenhain `PLANE POINTS`.
    PlanePoints = 7,
    /// Fanuc-style `G68.2`.
    G68_2 = 8,
    /// Syntec `G158`.
    G158 = 9,
    /// Beckhoff TwinCAT NC I `ROT`.
    TwincatRot = 10,
    /// Haas `G268`.
    G268 = 11,
    /// Fanuc-style `G68.3` (the plane from the tool direction, on a machine whose vertical
    /// axis is +Z [choice: a parameter of the control; `fanuc::g68_3` takes any]).
    G68_3 = 12,
    /// Heidenhain `PLANE PROJECTED`.
    PlaneProjected = 13,
}

impl Form {
    /// Every form, in code order.
    pub const ALL: [Form; 13] = [
        Form::Cycle800,
        Form::SinumerikRot,
        Form::SinumerikRots,
        Form::PlaneSpatial,
        Form::PlaneEuler,
        Form::PlaneVector,
        Form::PlanePoints,
        Form::G68_2,
        Form::G158,
        Form::TwincatRot,
        Form::G268,
        Form::G68_3,
        Form::PlaneProjected,
    ];

    /// The form of a code (1..=13), else [`Error::BadArgument`].
    ///
    /// ```
    /// use cncrot::dialects::form::Form;
    /// assert_eq!(Form::from_code(8), Ok(Form::G68_2));
    /// assert!(Form::from_code(0).is_err());
    /// ```
    pub fn from_code(code: i32) -> Result<Form, Error> {
        usize::try_from(code)
            .ok()
            .and_then(|c| c.checked_sub(1))
            .and_then(|i| Form::ALL.get(i).copied())
            .ok_or(Error::BadArgument)
    }
}

/// What a family declares about a form whose frame it computes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FormInfo {
    /// The form.
    pub form: Form,
    /// How many words it has.
    pub words: usize,
    /// Whether its words carry an origin (the others rotate about the active datum).
    pub origin: bool,
    /// Whether every frame can be written in it (`ROTS` cannot: its projection fixes the
    /// new X in a plane).
    pub writable: bool,
}

/// A form as named to the writer (`"PLANE SPATIAL"`, `"G158 P10157"`): the form and its
/// selector.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FormSpec {
    /// The form.
    pub form: Form,
    /// Its selector (`_MODE`, `P`, `Q`, the angle mode; 0 where the form has none).
    pub selector: i32,
}

/// What a controller family provides. Every function is called through the registry's
/// `match` (static dispatch: the no-panic proof sees through it), with the generic checks
/// already done: the line without its end and within `MAX_LINE`, a form's words counted and
/// finite, a frame's rotation valid.
pub(crate) trait Family {
    /// The longest block the reader accepts, in bytes without the line end.
    const MAX_LINE: usize;
    /// The forms whose frames this family computes (each form has exactly one owner).
    const FORMS: &'static [FormInfo];

    /// The words of `text` that are not its frame commands', appended to `out` (see
    /// [`super::program::rest`]); whether a word other than the block number is left.
    /// None by default: the family's frame commands stand alone on their blocks (its
    /// reader refuses other words beside one).
    fn rest(_text: &[u8], _out: &mut Out) -> bool {
        false
    }

    /// What one block does to `m` (any block of a program in this dialect: a command the
    /// family reads gives the next state, any other block is passed over or, if it changes
    /// the frame in a way the family does not follow, says so); only a malformed command
    /// the family reads is refused, with its column.
    fn read_line(m: &Modal, text: &[u8]) -> Result<Block, LineError>;

    /// Whether `m`, restored from elsewhere, is a state this family's reader can leave
    /// (the rotation itself is checked by the caller). Most families keep no angles.
    fn consistent(m: &Modal) -> bool {
        m.angles == [0.0; 3] || m.direct.is_some()
    }

    /// The form the writer is asked for by name (`text` trimmed of nothing: spaces around
    /// are the family's to skip), or [`Error::BadArgument`].
    fn parse_form(text: &[u8]) -> Result<FormSpec, Error>;

    /// Writes the block of `spec` with its words (`words.len()` is the form's count) and,
    /// where the block has words for them, the solution `choice` names
    /// ([`Error::NotAvailable`] where the block cannot say that choice) and the
    /// `positioning` (where [`Family::POSITIONING_IN_BLOCK`]). A block without such words
    /// writes none.
    fn write_line(
        spec: &FormSpec,
        words: &[f64],
        how: Motion,
        decimals: i32,
        out: &mut Out,
    ) -> Result<(), Error>;

    /// Whether the tilt block itself says how the machine moves to the plane (Heidenhain's
    /// `MOVE`/`TURN`/`STAY`).
    const POSITIONING_IN_BLOCK: bool = false;

    /// The block after a tilt of `spec` that moves the machine to it as `how` says
    /// (`G53.1`, `G53.6 P1`, `G253`), where the family has one; `None` where the tilt block
    /// says it or nothing can.
    fn positioning_block(spec: &FormSpec, how: Motion) -> Option<&'static [u8]> {
        let _ = (spec, how);
        None
    }

    /// The form whose words [`Family::write_line`] writes as an increment on the active
    /// tilt when the motion says `relative` (`G68.4` for `G68.2`, `PLANE RELATIV` from the
    /// spatial angles for every `PLANE`, `CYCLE800` with `_ST` 1, `AROT` for `ROT`); `None`
    /// where the family has no such command for `spec`.
    fn relative_form(spec: &FormSpec) -> Option<FormSpec> {
        let _ = spec;
        None
    }

    /// Whether the family's reader keeps a datum shift apart from the tilt, kept when the
    /// tilt is cancelled (Heidenhain's cycle 7, Fanuc-style `G52`); `false` where one frame
    /// holds both and a substituting command replaces it (SINUMERIK's `TRANS` and `ROT`).
    const KEEPS_SHIFT: bool = false;

    /// Writes the block or blocks (separated by `\n`) that make `shift` the datum shift,
    /// along the workpiece axes before any tilt, as the family's reader reads them back;
    /// [`Error::NotAvailable`] for a family without such a command.
    fn write_shift(shift: Vector, decimals: i32, out: &mut Out) -> Result<(), Error> {
        let _ = (shift, decimals, out);
        Err(Error::NotAvailable)
    }

    /// Whether the family's direct-mode block has origin words (`G158`'s `X Y Z`,
    /// `CYCLE800`'s `_X0 _Y0 _Z0`; `PLANE AXIAL` has none).
    const DIRECT_HAS_ORIGIN: bool = false;

    /// How the family's five-axis programs are written; `None`: not read.
    const TOOL_PATH: Option<&'static PathWords> = None;

    /// Writes the direct-mode block that positions the rotary axes as `direct` says
    /// (`PLANE AXIAL`, `G158 P10200`, `CYCLE800` direct), with its origin `origin` (zero for
    /// a block without origin words) and the positioning of `how` where the block says it,
    /// whatever form `spec` names for frames; [`Error::NotAvailable`] where the family has
    /// no direct mode or names the axes otherwise (letters, or places in the kinematics:
    /// one cannot become the other without the machine).
    fn write_direct(
        spec: &FormSpec,
        origin: Vector,
        direct: (Direct, [f64; 3]),
        how: Motion,
        decimals: i32,
        out: &mut Out,
    ) -> Result<(), Error> {
        let _ = (spec, origin, direct, how, decimals, out);
        Err(Error::NotAvailable)
    }

    /// Writes the block that cancels the tilt programmed with `spec` (`G69`, `PLANE RESET
    /// STAY`, `CYCLE800()`), what the writer gives for the identity frame, with the words of
    /// `how` the cancel has (`PLANE RESET TURN FMAX`); `false` (nothing written) where the
    /// form has no cancel of its own and zero words are its cancel, or where only the zero
    /// tilt turns the axes as `how` says (`G68.2` of zeros and `G53.1`, a `CYCLE800` of zero
    /// angles).
    fn write_cancel(
        spec: &FormSpec,
        how: Motion,
        decimals: i32,
        out: &mut Out,
    ) -> Result<bool, Error>;

    /// The frame of an owned form's words.
    fn form_frame(form: Form, selector: i32, words: &[f64]) -> Result<Frame, Error>;

    /// The words of an owned form that give `frame`, into `out[..count]`; whether the
    /// decomposition was singular.
    fn form_values(
        form: Form,
        selector: i32,
        frame: &Frame,
        out: &mut [f64; MAX_VALUES],
    ) -> Result<bool, Error>;
}

/// What a tilt block's words say beside the plane: the solution and how to move there.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Motion {
    /// The solution of the rotary axes.
    pub choice: AxisChoice,
    /// How the machine moves to the plane.
    pub positioning: Positioning,
    /// The retraction before the axes turn.
    pub retract: Retract,
    /// Its length (mm) for [`Retract::Tool`].
    pub retract_mm: f64,
    /// How fast they turn.
    pub feed: Feed,
    /// The feed rate (mm/min) for [`Feed::Rate`].
    pub feed_mm_min: f64,
    /// A free rotary table turns to the plane (`TABLE ROT`) instead of the coordinate
    /// system alone (`COORD ROT`, or no word).
    pub table_rot: bool,
    /// The block adds to the active tilt (`G68.4`, `PLANE RELATIV`, `CYCLE800` with `_ST`
    /// 1, `AROT`, `G158 P01…`): the words are the increment.
    pub relative: bool,
}

/// A command of a five-axis program (see [`PathWords`]).
pub(crate) enum PathCommand {
    /// A G or M code in tenths: `Code(b'G', 434)` is `G43.4`.
    Code(u8, u32),
    /// A name standing alone (`TRAORI`, `ORIRPY`; arguments in parentheses allowed).
    Name(&'static [u8]),
    /// Names in a row (`FUNCTION TCPM`).
    Phrase(&'static [&'static [u8]]),
}

/// How a dialect writes the programs of the five-axis transformation (read by
/// `dialects::toolpath`): the commands that switch it on and off, the words of the tool
/// direction, what is not a straight move.
pub(crate) struct PathWords {
    /// One-letter addresses whose words may run together (`G1X10.`); otherwise names,
    /// `=` optional after one letter and required after a name ending in digits (`A3=`).
    pub(crate) iso: bool,
    /// Words stand apart (Heidenhain: a letter right after a number is no new word, and
    /// makes the number unreadable); a `,` may stand for the decimal point.
    pub(crate) spaced: bool,
    /// SINUMERIK's exponent `EX` (`1.5EX3`).
    pub(crate) ex: bool,
    /// Switch the transformation on.
    pub(crate) on: &'static [PathCommand],
    /// Switch it off.
    pub(crate) off: &'static [PathCommand],
    /// The tool direction's components (`A3 B3 C3`, `TX TY TZ`, `I J K`).
    pub(crate) vector: [&'static [u8]; 3],
    /// Orientation angles (SINUMERIK `A2 B2 C2`).
    pub(crate) angles: Option<[&'static [u8]; 3]>,
    /// Commands that make the angles roll, pitch and yaw, or Euler angles.
    pub(crate) rpy: &'static [PathCommand],
    /// See `rpy`.
    pub(crate) euler: &'static [PathCommand],
    /// Commands that make coordinates incremental, absolute.
    pub(crate) incremental: &'static [PathCommand],
    /// See `incremental`.
    pub(crate) absolute: &'static [PathCommand],
    /// Commands that make the rotary letters `A B C` spatial angles (Heidenhain
    /// `FUNCTION TCPM … AXIS SPAT`), axis positions again; switching the transformation on
    /// or off makes them positions.
    pub(crate) spatial: &'static [PathCommand],
    /// See `spatial`.
    pub(crate) positions: &'static [PathCommand],
    /// An `I` before a letter makes that word incremental (Heidenhain `IX`).
    pub(crate) i_prefix: bool,
    /// The first words of the blocks that move in a straight line (Heidenhain `L`, `LN`);
    /// empty: every block with motion words.
    pub(crate) moves: &'static [&'static [u8]],
    /// Moves the reader does not follow: arcs, moves in machine coordinates, reference
    /// returns, canned cycles; and commands whose words change the frame the coordinates
    /// are read in (a datum shift, a rotation, a mirror, a scale): with or without
    /// coordinates, the block is not followed.
    pub(crate) arcs: &'static [PathCommand],
    /// Commands of a circular (or spline) mode, modal until one of `linear`: every motion
    /// block in it is an arc, not followed.
    pub(crate) circular: &'static [PathCommand],
    /// Commands of the straight moves (`G0`, `G1`): they end `circular`'s mode and
    /// `canned`'s.
    pub(crate) linear: &'static [PathCommand],
    /// Canned cycles, modal until one of `canned_off` or `linear` or `circular`: every
    /// motion block in it is a hole, not followed.
    pub(crate) canned: &'static [PathCommand],
    /// See `canned`.
    pub(crate) canned_off: &'static [PathCommand],
    /// Commands whose words are no coordinates and move nothing (a dwell `G4 X1.5`): the
    /// block is passed over.
    pub(crate) still: &'static [PathCommand],
    /// Commands that switch the transformation off at the end of their block (Heidenhain
    /// `M129`): a motion block with one is still a point.
    pub(crate) off_after: &'static [PathCommand],
    /// Moves whose end the reader does not know, with or without coordinate words (a
    /// contour element other than a line, a cycle or subprogram call, a program end): not
    /// followed, and the tip lost.
    pub(crate) loses: &'static [PathCommand],
    /// Words whose value changes the tip or the orientation in a way the reader does not
    /// compute (SINUMERIK `LEAD`, `TILT`, the surface normals `A4`…`C5`, the second curve
    /// `XH YH ZH`): the block is not followed, the tip and the orientation lost.
    pub(crate) unread: &'static [&'static [u8]],
    /// Cutter radius compensation on, off.
    pub(crate) compensation: &'static [PathCommand],
    /// See `compensation`.
    pub(crate) compensation_off: &'static [PathCommand],
    /// Commands that change the coordinates or the orientation's meaning in a way the
    /// reader does not compute (see `ToolPath::altered`), and the ones that end that.
    pub(crate) altering: &'static [PathCommand],
    /// See `altering`.
    pub(crate) unaltering: &'static [PathCommand],
    /// Work-offset selections the ISO and SINUMERIK `G` codes do not cover (Heidenhain's
    /// datum setting cycle): the coordinates after one are another frame's.
    pub(crate) offsets: &'static [PathCommand],
    /// Inch coordinates, millimetres.
    pub(crate) inch: &'static [PathCommand],
    /// See `inch`.
    pub(crate) metric: &'static [PathCommand],
}

/// The ISO dialects' five-axis programs, switched on by `on`, off by `G49`.
pub(crate) const fn iso_path(on: &'static [PathCommand], vector: [&'static [u8]; 3]) -> PathWords {
    use PathCommand::Code;
    PathWords {
        iso: true,
        spaced: false,
        ex: false,
        on,
        // `G43`/`G44` (tool length compensation alone) are of the same group as `G43.4`,
        // `G43.5` (Haas: `G234`): they end the transformation as `G49` does.
        off: &[
            PathCommand::Code(b'G', 490),
            PathCommand::Code(b'G', 430),
            PathCommand::Code(b'G', 440),
        ],
        vector,
        angles: None,
        rpy: &[],
        euler: &[],
        incremental: &[PathCommand::Code(b'G', 910)],
        absolute: &[PathCommand::Code(b'G', 900)],
        spatial: &[],
        positions: &[],
        i_prefix: false,
        moves: &[],
        arcs: &[
            // Reference and machine-coordinate moves.
            Code(b'G', 270),
            Code(b'G', 280),
            Code(b'G', 290),
            Code(b'G', 300),
            Code(b'G', 530),
            // Offsets, coordinate settings and conversions, macro calls with arguments.
            Code(b'G', 100),
            Code(b'G', 500),
            Code(b'G', 501),
            Code(b'G', 510),
            Code(b'G', 511),
            Code(b'G', 520),
            Code(b'G', 682),
            Code(b'G', 683),
            Code(b'G', 684),
        ],
        // Group 01: `G2`/`G3` stay in force until `G0`/`G1`, as do NURBS (`G6.2`) and
        // three-dimensional circles (`G2.4`/`G3.4`); the canned cycles (group 09, their X Y
        // the holes, their Z R depths and planes) until `G80` or a group 01 code.
        circular: &[
            Code(b'G', 20),
            Code(b'G', 30),
            Code(b'G', 62),
            Code(b'G', 24),
            Code(b'G', 34),
        ],
        linear: &[Code(b'G', 0), Code(b'G', 10)],
        canned: &[
            Code(b'G', 730),
            Code(b'G', 740),
            Code(b'G', 760),
            Code(b'G', 810),
            Code(b'G', 820),
            Code(b'G', 830),
            Code(b'G', 840),
            Code(b'G', 850),
            Code(b'G', 860),
            Code(b'G', 870),
            Code(b'G', 880),
            Code(b'G', 890),
        ],
        canned_off: &[Code(b'G', 800)],
        // A dwell: `G04 X1.5` waits 1.5 s.
        still: &[Code(b'G', 40)],
        off_after: &[],
        // Macro calls, subprogram calls and returns, program ends.
        loses: &[
            Code(b'G', 650),
            Code(b'G', 660),
            Code(b'G', 661),
            Code(b'M', 980),
            Code(b'M', 970),
            Code(b'M', 1980),
            Code(b'M', 990),
            Code(b'M', 20),
            Code(b'M', 300),
        ],
        unread: &[],
        // `G41`/`G42`, their 3-D forms (`G41.2`…`G42.6`), Haas `G141`.
        compensation: &[
            Code(b'G', 410),
            Code(b'G', 420),
            Code(b'G', 412),
            Code(b'G', 422),
            Code(b'G', 413),
            Code(b'G', 414),
            Code(b'G', 415),
            Code(b'G', 416),
            Code(b'G', 424),
            Code(b'G', 425),
            Code(b'G', 426),
            Code(b'G', 1410),
        ],
        compensation_off: &[Code(b'G', 400)],
        // Rotation in the plane, scaling, mirroring, a position set; `G10` writes offset
        // tables (taken as a work offset's, which the coordinates are in).
        altering: &[
            Code(b'G', 680),
            Code(b'G', 510),
            Code(b'G', 511),
            Code(b'G', 920),
        ],
        unaltering: &[
            Code(b'G', 690),
            Code(b'G', 500),
            Code(b'G', 501),
            Code(b'G', 921),
        ],
        offsets: &[],
        inch: &[Code(b'G', 200)],
        metric: &[Code(b'G', 210)],
    }
}

/// A form without a selector: anything but 0 is [`Error::BadArgument`].
pub(crate) fn no_selector(selector: i32) -> Result<(), Error> {
    if selector == 0 {
        Ok(())
    } else {
        Err(Error::BadArgument)
    }
}

/// Three words from `at` (0 beyond the end).
pub(crate) fn v3(w: &[f64], at: usize) -> Vector {
    core::array::from_fn(|k| w.get(at + k).copied().unwrap_or(0.0))
}

/// Puts three words at `at`.
pub(crate) fn put(out: &mut [f64; MAX_VALUES], at: usize, v: [f64; 3]) {
    for (k, x) in v.into_iter().enumerate() {
        if let Some(slot) = out.get_mut(at + k) {
            *slot = x;
        }
    }
}
