"""A batch's results table: one row per finished run, written as it finishes.

Formats by suffix: `.csv`, `.jsonl` (one JSON object a line) and `.parquet` (pyarrow). CSV and JSON
Lines are appended and flushed row by row; a Parquet file is rewritten whole (to a temporary file,
then renamed) after each row. Either way an interrupted batch loses no finished row, and
`--resume` reads the table back to skip the runs it holds.

Columns: `run`, the plan's parameters (`world`, `controller.ROBOT`, `args.ROBOT`, `field.KEY`,
`seed`), the outcome (`status`, `score`, `message`, `end_reason`, `sim_time`, `wall_time`,
`quit_status`, `attempts`), then for each robot `ROBOT.status`, `.exit_code`, `.x`, `.y`, `.z`,
`.distance`.
"""

from __future__ import annotations

import csv
import json
import os
from pathlib import Path
from typing import Any

OUTCOME_COLUMNS = ["status", "score", "message", "end_reason", "sim_time", "wall_time", "quit_status", "attempts"]
ROBOT_COLUMNS = ["status", "exit_code", "x", "y", "z", "distance"]


def columns(params: list[str], robots: list[str]) -> list[str]:
    """The table's columns for a plan's parameter names and robots."""
    return ["run", *params, *OUTCOME_COLUMNS, *(f"{r}.{c}" for r in robots for c in ROBOT_COLUMNS)]


class Table:
    """Appends rows to the results file; knows which runs it already holds."""

    def __init__(self, path: Path, params: list[str], robots: list[str], resume: bool) -> None:
        self.path = path
        self.params = params
        self.columns = columns(params, robots)
        self.suffix = path.suffix.lower()
        self.rows: list[dict[str, Any]] = self._read() if resume and path.exists() else []
        self.done = {self.key(row) for row in self.rows}
        if self.suffix == ".csv" and not (resume and path.exists() and path.stat().st_size):
            with path.open("w", encoding="utf-8", newline="") as stream:
                csv.writer(stream).writerow(self.columns)
        elif self.suffix == ".jsonl" and not resume:
            path.write_text("", encoding="utf-8")
        elif self.suffix == ".parquet" and not resume:
            self._write_parquet()

    def key(self, row: dict[str, Any]) -> str:
        """A row's run identity (its parameters), as `Job.key` gives it."""
        return json.dumps({p: "" if row.get(p) is None else str(row.get(p)) for p in self.params}, sort_keys=True)

    def append(self, row: dict[str, Any]) -> None:
        """Write one finished run."""
        row = {c: row.get(c) for c in self.columns}
        self.rows.append(row)
        self.done.add(self.key(row))
        if self.suffix == ".csv":
            with self.path.open("a", encoding="utf-8", newline="") as stream:
                csv.writer(stream).writerow(["" if row[c] is None else row[c] for c in self.columns])
        elif self.suffix == ".jsonl":
            with self.path.open("a", encoding="utf-8") as stream:
                stream.write(json.dumps(row) + "\n")
        else:
            self._write_parquet()

    def _read(self) -> list[dict[str, Any]]:
        if self.suffix == ".csv":
            with self.path.open(encoding="utf-8", newline="") as stream:
                return list(csv.DictReader(stream))
        if self.suffix == ".jsonl":
            lines = self.path.read_text(encoding="utf-8").splitlines()
            return [json.loads(line) for line in lines if line.strip().endswith("}")]  # a torn last line is dropped
        import pyarrow.parquet as pq

        return pq.read_table(self.path).to_pylist()

    def _write_parquet(self) -> None:
        import pyarrow as pa
        import pyarrow.parquet as pq

        fields = [pa.field(c, _arrow_type(c, pa)) for c in self.columns]
        schema = pa.schema(fields)
        data = {c: [_cast(row.get(c), f.type, pa) for row in self.rows] for c, f in zip(self.columns, fields,
                                                                                       strict=True)}
        temporary = self.path.with_name(self.path.name + ".tmp")
        pq.write_table(pa.table(data, schema=schema), temporary)
        os.replace(temporary, self.path)


def _arrow_type(column: str, pa: Any) -> Any:
    name = column.rsplit(".", 1)[-1] if "." in column and not column.startswith(("field.", "args.", "controller."))\
        else column
    if name in ("score", "sim_time", "wall_time", "x", "y", "z", "distance"):
        return pa.float64()
    if name in ("run", "quit_status", "attempts", "exit_code"):
        return pa.int64()
    return pa.string()


def _cast(value: Any, arrow_type: Any, pa: Any) -> Any:
    if value is None or value == "":
        return None
    if arrow_type == pa.float64():
        return float(value)
    if arrow_type == pa.int64():
        return int(value)
    return str(value)
