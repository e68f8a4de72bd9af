"""REXS (Reducer EXchange Specification, FVA) bevel stages in and out (docs/exchange.md).

A case's bevel stage is written as a REXS model — ``bevel_stage``, both ``bevel_gear``
blanks, per member and flank a ``bevel_gear_flank`` with its ``bevel_gear_tool`` and
``bevel_gear_manufacturing_settings`` joined by ``manufacturing_step`` relations, the
operating point as a load spectrum — to ``.rexs`` (XML) or ``.rexsj`` (JSON), REXS 1.7 or
2.0.0; every file is checked against the published file schema and the attribute database
before it is written, and every file read is checked the same way.

Public
------
export_rexs          write a case (and analysis results) as a REXS file
import_rexs          read a REXS file: a Case, or a basic design mapping (blank data only)
read_rexs            a REXS file as a validated Model
write_rexs           write a Model, validated, atomically
validate_file        the problems of a REXS file (empty: valid); ``validate_rexs`` the same
VERSIONS             the REXS versions supported
"""

from contact.exchange.rexs.api import (
    ImportedStage,
    export_rexs,
    import_rexs,
    read_rexs,
    write_rexs,
)
from contact.exchange.rexs.database import VERSIONS
from contact.exchange.rexs.validate import RexsValidationError, validate_file

#: :func:`validate_file` under the name ``contact`` exports it by
validate_rexs = validate_file

__all__ = ["VERSIONS", "ImportedStage", "RexsValidationError", "export_rexs", "import_rexs",
           "read_rexs", "validate_file", "validate_rexs", "write_rexs"]
