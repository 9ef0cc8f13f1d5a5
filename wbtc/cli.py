"""The `wbtc` command line. The only place that prints diagnostics and chooses exit codes.

A `WbtcError` becomes `path:line:col: error: message`, the source line and a caret on stderr, and
exit code 1; the user never sees a traceback for a mistake in a world file.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Annotated, TypeVar

import typer

from wbtc.errors import Diagnostic, WbtcError, render_diagnostic
from wbtc.gl_platform import import_mujoco_without_gl

app = typer.Typer(
    name="wbtc",
    help="Run Webots worlds and their Python controllers without Webots (MuJoCo inside).",
    add_completion=False,
    no_args_is_help=True,
    pretty_exceptions_enable=False,
)



@app.callback()
def _root() -> None:
    """Run Webots worlds and their Python controllers without Webots (MuJoCo inside)."""


#: Diagnostics printed for one failure before the rest are counted.
SHOWN_ERRORS = 20
T = TypeVar("T")


def _print_diagnostics(diagnostics: list[Diagnostic]) -> None:
    color = sys.stderr.isatty()
    for diag in diagnostics[:SHOWN_ERRORS]:
        typer.echo(render_diagnostic(diag, color=color), err=True)
    rest = diagnostics[SHOWN_ERRORS:]
    if rest:
        kinds = {d.severity for d in rest}
        kind = "errors" if kinds == {"error"} else "warnings" if kinds == {"warning"} else "errors and warnings"
        typer.echo(f"... and {len(rest)} more {kind}", err=True)


def _guard(action: Callable[[], T]) -> T:
    try:
        return action()
    except WbtcError as exc:
        _print_diagnostics(exc.diagnostics)
        count = len(exc.diagnostics)
        if count > 1:
            typer.echo(f"{count} errors", err=True)
        raise typer.Exit(1) from None


@app.command()
def check(
    world: Annotated[Path, typer.Argument(help="The .wbt world file.")],
    json_output: Annotated[bool, typer.Option("--json", help="Print one JSON object.")] = False,
    strict: Annotated[bool, typer.Option(
        "--strict", help="Unresolved PROTOs, compile errors and controllers wbtc cannot run are errors.")] = False,
) -> None:
    """Say what is in a world (version, axes, robots, devices, PROTOs) and what is wrong with it."""
    from wbtc.check import check_report, format_report
    from wbtc.proto.expand import expand_scene
    from wbtc.readiness import run_checks
    from wbtc.scene import build_scene
    from wbtc.vrml import parse_file

    if not world.is_file():
        _guard(lambda: _missing(world))
    scene, expansion = _guard(lambda: expand_scene(build_scene(parse_file(world)), strict=strict))
    problems = run_checks(scene, world)
    if strict and problems:
        _guard(lambda: _fail_all(problems))
    sources = expansion.sources
    report = check_report(scene, expansion.counts, lambda n: sources[n].label if sources.get(n) else None)
    report.warnings += [str(p) for p in problems]
    if json_output:
        typer.echo(report.model_dump_json())
        return
    typer.echo(format_report(report))


_ODE_CONTACTS_HELP = "Contacts as Webots' ODE ones (softERP, softCFM: heavy bodies sink), hard Coulomb friction."


@app.command("compile")
def compile_command(
    world: Annotated[Path, typer.Argument(help="The .wbt world file.")],
    output: Annotated[Path | None, typer.Option("-o", "--output", help="The MJCF file to write.")] = None,
    strict: Annotated[bool, typer.Option("--strict", help="Unhonoured fields and unresolved PROTOs are errors.")]
    = False,
    substep: Annotated[float, typer.Option("--physics-step", min=0.001, help="Longest MuJoCo substep, ms.")] = 2.0,
    ode_contacts: Annotated[bool, typer.Option("--ode-contacts", help=_ODE_CONTACTS_HELP)] = False,
) -> None:
    """Compile a world to a MuJoCo model (MJCF), with its textures beside it."""
    import_mujoco_without_gl()  # compiling draws nothing
    from wbtc.compile.context import CompileOptions
    from wbtc.compile.output import check_output_folder, write_mjcf
    from wbtc.pipeline import compile_world

    out = output or world.with_suffix(".xml")
    _guard(lambda: check_output_folder(out))  # before compiling, which can take seconds
    # No paint layers: plain MuJoCo has no Pen to paint them (CompileOptions.paint).
    options = CompileOptions(max_substep_ms=substep, strict=strict, ode_contacts=ode_contacts, paint=False)
    result, expansion = _guard(lambda: compile_world(world, options))
    _print_diagnostics(expansion.warnings + result.warnings)
    _guard(lambda: write_mjcf(result.spec, out))
    typer.echo(f"{out}: {result.summary()}")


@app.command()
def run(
    world: Annotated[Path, typer.Argument(help="The .wbt world file.")],
    duration: Annotated[float | None, typer.Option("--duration", min=0.0, help="Simulated seconds to run.")] = None,
    headless: Annotated[bool, typer.Option("--headless", help="No viewer, even with a display.")] = False,
    realtime: Annotated[bool, typer.Option("--realtime", help="Run no faster than real time.")] = False,
    seed: Annotated[int | None, typer.Option("--seed", help="Seed of sensor noise (default: randomSeed).")] = None,
    json_output: Annotated[bool, typer.Option("--json", help="Print one JSON object at the end.")] = False,
    trace: Annotated[Path | None, typer.Option("--trace", help="Write every robot's pose to a CSV file.")] = None,
    keys: Annotated[Path | None, typer.Option("--keys", help="Replay timed key presses (`time_s key` lines).")]
    = None,
    physics_step: Annotated[float, typer.Option("--physics-step", min=0.001, help="Longest MuJoCo substep, ms.")] = 2.0,
    ode_contacts: Annotated[bool, typer.Option("--ode-contacts", help=_ODE_CONTACTS_HELP)] = False,
    no_noise: Annotated[bool, typer.Option("--no-noise", help="Turn sensor noise off.")] = False,
    record: Annotated[Path | None, typer.Option(
        "--record", help="Write a video of the Viewpoint (.mp4 or .gif), or a page replaying the run (.html).")]
    = None,
) -> None:
    """Simulate a world and run its robots' Python controllers."""
    import_mujoco_without_gl()  # a run without cameras never loads OpenGL
    from wbtc.runtime.launch import launch

    try:
        code = _guard(lambda: launch(world, duration=duration, headless=headless, realtime=realtime, seed=seed,
                                     json_output=json_output, trace=trace, keys=keys, physics_step=physics_step,
                                     ode_contacts=ode_contacts, noise=not no_noise, warn=_print_diagnostics,
                                     record=record))
    except KeyboardInterrupt as stop:  # a second Ctrl-C or SIGTERM, or one before the world steps
        typer.echo("\nwbtc run: stopped at once; no video, page or trace of this run was kept", err=True)
        raise typer.Exit(128 + getattr(stop, "signal", 2)) from None  # wbtc.runtime.interrupt.Stopped
    raise typer.Exit(code)


@app.command()
def batch(
    plan: Annotated[Path, typer.Argument(help="The plan (TOML): worlds, controllers, args, fields, seeds, grader.")],
    workers: Annotated[int | None, typer.Option("--workers", help="Runs at once (default: the cores).")] = None,
    resume: Annotated[bool, typer.Option("--resume", help="Skip the runs the results table already holds.")]
    = False,
    ray: Annotated[str | None, typer.Option("--ray", help="Run on a Ray cluster (ADDRESS, ray://..., or local).")]
    = None,
    output: Annotated[Path | None, typer.Option("-o", "--output", help="The results table (.csv, .jsonl, .parquet).")]
    = None,
) -> None:
    """Run every combination of a plan on all cores (or a Ray cluster), graded into one table."""
    from wbtc.batch.runner import run_batch

    if workers is not None and workers < 1:
        _guard(lambda: _fail("--workers must be at least 1"))
    try:
        summary = _guard(lambda: run_batch(plan, workers=workers, resume=resume, ray=ray, output=output))
    except KeyboardInterrupt:
        typer.echo("\nwbtc batch: interrupted; finished runs are in the table (--resume goes on)", err=True)
        raise typer.Exit(130) from None
    typer.echo(summary.line())


def _fail(message: str) -> None:
    raise WbtcError(message)


def _fail_all(problems: list[Diagnostic]) -> None:
    raise WbtcError("", diagnostics=[Diagnostic(p.message, p.span, "error", p.hint) for p in problems])


def _missing(path: Path) -> None:
    raise WbtcError(f"no such world file: {path}")


#: Commands whose process may end without the interpreter's teardown (see `main`).
_QUICK_EXIT = {"run", "compile", "check"}


def main() -> None:
    """Entry point of the `wbtc` console script.

    Once `run`, `compile` or `check` is done (files closed, output flushed, controllers stopped), the
    process ends at once: the interpreter's own teardown (freeing numpy, MuJoCo and lark objects
    module by module) would add about 60 ms to every `wbtc run`. `batch` ends normally: a Ray
    client shuts its connection down at exit.
    """
    try:
        app()
    except SystemExit as exc:
        if len(sys.argv) < 2 or sys.argv[1] not in _QUICK_EXIT:
            raise
        code = exc.code
        if isinstance(code, str):
            print(code, file=sys.stderr)
            code = 1
        sys.stdout.flush()
        sys.stderr.flush()
        files = sys.modules.get("wbtc.proto.template_files")
        if files is not None:  # what atexit would have cleaned: templates' temporary files
            files.remove_temporary_files()
        os._exit(int(code or 0))


if __name__ == "__main__":
    main()
