//! The one list of controller families, and the dispatch generated from it.
//!
//! Each line of `families!` registers a family: its [`Dialect`] variant with the C code, and
//! the unit struct that implements [`Family`] in the family's own file. Everything that
//! depends on the dialect or a form's owner (`Program::line`, `write_line`, `form_frame`,
//! `form_values`, the C boundary's codes) goes through the `match`es generated here: static
//! dispatch, no function pointers, so the no-panic proof sees every path.

use super::family::{
    Block, Direct, Family, Form, FormInfo, FormSpec, Modal, Motion, PathWords, MAX_VALUES,
};
use super::{fanuc, haas, heidenhain, sinumerik, syntec, twincat};
use crate::text::number::Out;
use crate::text::scan::LineError;
use crate::{Error, Frame, Vector};

macro_rules! families {
    ($($(#[$doc:meta])* $name:ident = $code:literal => $family:ty,)*) => {
        /// How many families there are.
        const COUNT: usize = [$($code),*].len();

        /// A controller family whose program lines the library reads and writes.
        ///
        /// ```
        /// use cncrot::dialects::program::Dialect;
        /// assert_eq!(Dialect::from_code(2), Ok(Dialect::Heidenhain));
        /// assert_eq!(Dialect::Heidenhain.max_line(), 254);
        /// ```
        #[derive(Clone, Copy, Debug, PartialEq, Eq)]
        pub enum Dialect {
            $($(#[$doc])* $name = $code,)*
        }

        impl Dialect {
            /// Every dialect, in code order.
            pub const ALL: [Dialect; COUNT] = [$(Dialect::$name,)*];

            /// The longest block the dialect's reader accepts, in bytes without the line
            /// end: SINUMERIK 512 (its manual's limit for a block), Heidenhain 254
            /// \[choice\], the others 256 \[choice\].
            pub const fn max_line(self) -> usize {
                match self {
                    $(Dialect::$name => <$family>::MAX_LINE,)*
                }
            }

            /// The forms whose frames the dialect's family computes.
            pub(crate) fn forms(self) -> &'static [FormInfo] {
                match self {
                    $(Dialect::$name => <$family>::FORMS,)*
                }
            }

            pub(crate) fn rest(self, text: &[u8], out: &mut Out) -> bool {
                match self {
                    $(Dialect::$name => <$family>::rest(text, out),)*
                }
            }

            pub(crate) fn read_line(self, m: &Modal, text: &[u8]) -> Result<Block, LineError> {
                match self {
                    $(Dialect::$name => <$family>::read_line(m, text),)*
                }
            }

            pub(crate) fn consistent(self, m: &Modal) -> bool {
                match self {
                    $(Dialect::$name => <$family>::consistent(m),)*
                }
            }

            pub(crate) fn parse_form(self, text: &[u8]) -> Result<FormSpec, Error> {
                match self {
                    $(Dialect::$name => <$family>::parse_form(text),)*
                }
            }

            pub(crate) fn write_cancel(
                self,
                spec: &FormSpec,
                how: Motion,
                decimals: i32,
                out: &mut Out,
            ) -> Result<bool, Error> {
                match self {
                    $(Dialect::$name => <$family>::write_cancel(spec, how, decimals, out),)*
                }
            }

            pub(crate) fn write_line(
                self,
                spec: &FormSpec,
                words: &[f64],
                how: Motion,
                decimals: i32,
                out: &mut Out,
            ) -> Result<(), Error> {
                match self {
                    $(Dialect::$name => <$family>::write_line(spec, words, how, decimals, out),)*
                }
            }

            pub(crate) const fn positioning_in_block(self) -> bool {
                match self {
                    $(Dialect::$name => <$family>::POSITIONING_IN_BLOCK,)*
                }
            }

            pub(crate) fn positioning_block(
                self,
                spec: &FormSpec,
                how: Motion,
            ) -> Option<&'static [u8]> {
                match self {
                    $(Dialect::$name => <$family>::positioning_block(spec, how),)*
                }
            }

            pub(crate) fn relative_form(self, spec: &FormSpec) -> Option<FormSpec> {
                match self {
                    $(Dialect::$name => <$family>::relative_form(spec),)*
                }
            }

            pub(crate) const fn keeps_shift(self) -> bool {
                match self {
                    $(Dialect::$name => <$family>::KEEPS_SHIFT,)*
                }
            }

            pub(crate) fn write_shift(
                self,
                shift: Vector,
                decimals: i32,
                out: &mut Out,
            ) -> Result<(), Error> {
                match self {
                    $(Dialect::$name => <$family>::write_shift(shift, decimals, out),)*
                }
            }

            pub(crate) const fn tool_path(self) -> Option<&'static PathWords> {
                match self {
                    $(Dialect::$name => <$family>::TOOL_PATH,)*
                }
            }

            pub(crate) const fn direct_has_origin(self) -> bool {
                match self {
                    $(Dialect::$name => <$family>::DIRECT_HAS_ORIGIN,)*
                }
            }

            pub(crate) fn write_direct(
                self,
                spec: &FormSpec,
                origin: Vector,
                direct: (Direct, [f64; 3]),
                how: Motion,
                decimals: i32,
                out: &mut Out,
            ) -> Result<(), Error> {
                match self {
                    $(Dialect::$name => {
                        <$family>::write_direct(spec, origin, direct, how, decimals, out)
                    })*
                }
            }

            pub(crate) fn form_frame(
                self,
                form: Form,
                selector: i32,
                words: &[f64],
            ) -> Result<Frame, Error> {
                match self {
                    $(Dialect::$name => <$family>::form_frame(form, selector, words),)*
                }
            }

            pub(crate) fn form_values(
                self,
                form: Form,
                selector: i32,
                frame: &Frame,
                out: &mut [f64; MAX_VALUES],
            ) -> Result<bool, Error> {
                match self {
                    $(Dialect::$name => <$family>::form_values(form, selector, frame, out),)*
                }
            }
        }
    };
}

families! {
    /// Siemens SINUMERIK (`CYCLE800`, `CYCLE600`, `ROT`/`AROT`/`CROT`, `ROTS`, `TRANS`).
    Sinumerik = 1 => sinumerik::Sinumerik,
    /// Heidenhain TNC plain language (`PLANE …`).
    Heidenhain = 2 => heidenhain::Heidenhain,
    /// Fanuc and the controls that read its `G68.2`/`G68.4`/`G69`.
    Fanuc = 3 => fanuc::Fanuc,
    /// Syntec (`G158`, and its Fanuc-style `G68.2` mode).
    Syntec = 4 => syntec::Syntec,
    /// Beckhoff TwinCAT NC I (`ROT`, `AROT`, the zero offset shift `G58`).
    Twincat = 5 => twincat::Twincat,
    /// Haas (`G268`, `G269`).
    Haas = 6 => haas::Haas,
}

impl Dialect {
    /// The dialect of a code, else [`Error::BadArgument`].
    pub fn from_code(code: i32) -> Result<Dialect, Error> {
        Dialect::ALL
            .iter()
            .copied()
            .find(|&d| d as i32 == code)
            .ok_or(Error::BadArgument)
    }
}

impl Form {
    /// The family that computes this form, and what it declares about it.
    pub(crate) fn owner(self) -> Option<(Dialect, &'static FormInfo)> {
        Dialect::ALL
            .iter()
            .find_map(|&d| d.forms().iter().find(|i| i.form == self).map(|i| (d, i)))
    }

    /// How many words the form has.
    pub fn count(self) -> usize {
        self.owner().map_or(0, |(_, i)| i.words)
    }

    /// Whether [`form_values`](super::form::form_values) can express every frame in this
    /// form (`ROTS` cannot: its projection fixes the new X in a plane).
    pub fn writable(self) -> bool {
        self.owner().is_some_and(|(_, i)| i.writable)
    }

    /// Whether the form's words carry an origin (the others describe a rotation about the
    /// active datum).
    pub fn has_origin(self) -> bool {
        self.owner().is_some_and(|(_, i)| i.origin)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Codes are unique and dense from 1, and every form has exactly one owner.
    #[test]
    fn the_registry_is_consistent() {
        for (k, d) in Dialect::ALL.iter().enumerate() {
            assert_eq!(*d as usize, k + 1);
            assert_eq!(Dialect::from_code(k as i32 + 1), Ok(*d));
        }
        assert!(Dialect::from_code(0).is_err());
        assert!(Dialect::from_code(Dialect::ALL.len() as i32 + 1).is_err());
        for form in Form::ALL {
            let owners = Dialect::ALL
                .iter()
                .filter(|d| d.forms().iter().any(|i| i.form == form))
                .count();
            assert_eq!(owners, 1, "{form:?}");
            assert!((1..=MAX_VALUES).contains(&form.count()), "{form:?}");
        }
    }
}
