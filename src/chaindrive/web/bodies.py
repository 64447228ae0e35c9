"""Request bodies of the JSON API, each validated by its schema (a pydantic model).

A body that is not JSON is answered 400 (``{"error": "malformed JSON ..."}``); a JSON
body that does not match the schema 422, naming each field (``{"errors": {field:
message}}``). Nothing in a body reaches a computation unchecked, and no body gives a 500.
The models also give the OpenAPI schema of the routes (so schemathesis generates them).
"""

from __future__ import annotations

import json
from typing import Any, Literal

from fastapi.responses import JSONResponse
from pydantic import BaseModel, ConfigDict, Field, StrictInt, ValidationError

__all__ = ["SimulationBody", "read_body", "openapi_body", "MAX_BODY_BYTES"]

#: Largest JSON body read [bytes] (the studio state of a design is the longest field).
MAX_BODY_BYTES = 64_000


class SimulationBody(BaseModel):
    """``POST /api/jobs/simulate``: the simulation page's fields (quantities with their unit)."""

    model_config = ConfigDict(extra="forbid")

    example: Literal["link", "roller", "studio"] | None = Field(
        default=None, description="link | roller | studio (the studio's design, given in design)")
    speed: str | None = Field(default=None, max_length=64, description="wheel speed, e.g. '5 rad/s' (with its unit)")
    load: str | None = Field(default=None, max_length=64, description="load torque, e.g. '2000 N*m' (with its unit)")
    duration: str | None = Field(default=None, max_length=64, description="simulated time, e.g. '0.5 s' (with its unit)")
    frames: str | StrictInt | None = Field(default=None, description="animation frames, a whole number")
    design: str | None = Field(default=None, max_length=4000,
                               description="the studio's state as its query string (example = studio)")


def openapi_body(model: type[BaseModel]) -> dict[str, Any]:
    """``openapi_extra`` of a route whose JSON body is ``model`` (forms accepted too)."""
    schema = model.model_json_schema()
    return {"requestBody": {"required": False, "content": {
        "application/json": {"schema": schema},
        "application/x-www-form-urlencoded": {"schema": schema}}}}


def _refused(status: int, errors: dict[str, str] | None = None, error: str | None = None) -> JSONResponse:
    errors = errors or {}
    text = error or "; ".join(f"{k}: {v}" for k, v in errors.items())
    return JSONResponse({"errors": errors, "error": text} if errors else {"error": text}, status_code=status)


def validate_body(model: type[BaseModel], raw: bytes) -> tuple[dict[str, Any] | None, JSONResponse | None]:
    """The fields a JSON body sets (``None`` for an empty body), or the refusal to send.

    Examples
    --------
    >>> validate_body(SimulationBody, b'{"speed": "5 rad/s"}')
    ({'speed': '5 rad/s'}, None)
    >>> validate_body(SimulationBody, b"[1,2")[1].status_code
    400
    >>> json.loads(validate_body(SimulationBody, b"null")[1].body)["errors"]
    {'body': 'must be a JSON object with the fields example, speed, load, duration, frames, design'}
    >>> json.loads(validate_body(SimulationBody, b'{"frames": 1.5}')[1].body)["errors"]["frames"]
    'Input should be a valid string (or a whole number)'
    """
    if not raw.strip():
        return {}, None
    if len(raw) > MAX_BODY_BYTES:
        return None, _refused(413, error=f"the body is longer than {MAX_BODY_BYTES} bytes")
    try:
        data = json.loads(raw)
    except (ValueError, RecursionError) as exc:
        where = f" at character {exc.pos}" if isinstance(exc, json.JSONDecodeError) else ""
        return None, _refused(400, error=f"malformed JSON{where}: send a JSON object, e.g. "
                                         '{"example": "link", "speed": "5 rad/s"}')
    if not isinstance(data, dict):
        names = ", ".join(model.model_fields)
        return None, _refused(422, {"body": f"must be a JSON object with the fields {names}"})
    try:
        parsed = model.model_validate(data)
    except ValidationError as exc:
        errors: dict[str, str] = {}
        for e in exc.errors(include_url=False):
            name = str(e["loc"][0]) if e["loc"] else "body"
            if name not in errors:
                message = e["msg"]
                if e["type"] == "extra_forbidden":
                    message = f"unknown field; the fields are {', '.join(model.model_fields)}"
                elif e["type"] in ("string_type", "float_type", "int_type", "int_from_float"):
                    message = "Input should be a valid string (or a whole number)" if name == "frames" else \
                        "Input should be a string: the quantity with its unit, e.g. '5 rad/s'"
                errors[name] = message
        return None, _refused(422, errors)
    return parsed.model_dump(exclude_unset=True), None


async def read_body(request: Any, model: type[BaseModel]) -> tuple[dict[str, Any] | None, JSONResponse | None]:
    """The fields of a form or JSON request body (validated), or the refusal to send."""
    kind = request.headers.get("content-type", "")
    if "form" in kind:
        try:
            form = await request.form()
        except Exception:  # noqa: BLE001 - a broken multipart body is the client's error
            return None, _refused(400, error="malformed form body")
        data = {k: v for k, v in form.items() if isinstance(v, str)}
        return validate_body(model, json.dumps(data).encode())
    raw = await request.body()
    return validate_body(model, raw)
