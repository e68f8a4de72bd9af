"""``ltca synthesize``'s check that the case it writes can be analysed: moved to
:mod:`contact.optimize.written_contact` (issue 71, branch api88: the Python API's
:func:`contact.optimize.synthesized_case.synthesize_case` makes the same check); the names
kept here for existing imports."""

from contact.optimize.written_contact import (  # noqa: F401
    checked_contact,
    coast_note,
    refusal_text,
    unloaded_contact_failure,
)
