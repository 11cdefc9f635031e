"""Errors the generator reports to its user: always `file:line: message`, never a traceback.

Codes are stable (listed in docs/errors.md): R2V1xx parse, R2V2xx mapping, R2V3xx template/output.
"""
from __future__ import annotations


class GeneratorError(Exception):
    """Any failure that stops generation; the CLI prints it and exits with 1."""

    code = "R2V100"

    def __init__(self, message: str, code: str | None = None) -> None:
        super().__init__(message)
        self.message = message
        if code is not None:
            self.code = code

    def __str__(self) -> str:
        return f"error {self.code}: {self.message}"


class SpecError(GeneratorError):
    """A malformed spec or an unresolvable type, located in its file."""

    def __init__(self, path: str, line: int, message: str, code: str = "R2V101") -> None:
        super().__init__(message, code)
        self.path = path
        self.line = line

    def __str__(self) -> str:
        return f"{self.path}:{self.line}: {self.message} [{self.code}]"


# Parse error codes, one per kind of mistake (tests assert on them).
BAD_LINE = "R2V101"
BAD_TYPE = "R2V102"
BAD_NAME = "R2V103"
BAD_VALUE = "R2V104"
DUPLICATE = "R2V105"
UNKNOWN_TYPE = "R2V106"
BAD_SERVICE = "R2V107"
BAD_PATH = "R2V108"

# Mapping error codes (mapping.py and the kinds/ hooks): R2V201 file/TOML, R2V202 rule keys,
# R2V203 unknown ROS type, R2V204 unknown kind / VTK type, R2V205 field path, R2V206 duplicate,
# R2V207 lengths.
MAPPING_BAD_FILE = "R2V201"
MAPPING_BAD_KEY = "R2V202"
MAPPING_UNKNOWN_ROS_TYPE = "R2V203"
MAPPING_BAD_KIND = "R2V204"
MAPPING_BAD_FIELD = "R2V205"
MAPPING_DUPLICATE = "R2V206"
MAPPING_BAD_LENGTHS = "R2V207"
