// A typed client on the generated types: what `make test` compiles with `tsc --strict` to show
// that the document types every documented response (no `unknown`).
import type { components, paths } from "./openapi";

type Schemas = components["schemas"];
export type Curve = Schemas["CurveResponse"];
export type CurveMP = Schemas["CurveResponseMP"];
export type Problem = Schemas["Problem"];
type CurveOk = paths["/discretizations/d4b"]["get"]["responses"][200]["content"]["application/json"];
type CurveError = paths["/discretizations/d4b"]["get"]["responses"][422]["content"]["application/problem+json"];
type Catalog = paths["/discretizations"]["get"]["responses"][200]["content"]["application/json"];
type Erratum = paths["/errata/{erratum_id}"]["get"]["responses"][200]["content"]["application/json"];

export class ProblemError extends Error {
  constructor(readonly problem: Problem) {
    super(`${problem.title}: ${problem.detail}`);
  }
}

async function json<T>(response: Response): Promise<T> {
  if (!response.ok) {
    const problem: CurveError = await response.json();
    throw new ProblemError(problem);
  }
  return (await response.json()) as T;
}

/** A float64 curve: coordinates are numbers. */
export async function curve(api: string, query: string): Promise<Curve> {
  return json<Curve>(await fetch(`${api}/discretizations/d4b?${query}`));
}

/** An mp curve: coordinates are decimal strings. */
export async function curveMP(api: string, query: string): Promise<CurveMP> {
  return json<CurveMP>(await fetch(`${api}/discretizations/d4b?precision=mp&${query}`));
}

export function width(c: Curve): number {
  const xs = c.vertices.map(([x]) => x);
  return Math.max(...xs) - Math.min(...xs);
}

export function firstDigits(c: CurveMP): string {
  return c.vertices[0][1].slice(0, 10);
}

export function either(c: CurveOk): number | string {
  return c.vertices[0][0];
}

export function failedChecks(c: Curve): string[] {
  return c.checks.filter((check) => check.holds === false).map((check) => check.id);
}

export function errataLinks(c: Curve): string[] {
  return c.checks.flatMap((check) => (check.erratum ? [check.erratum.link] : []));
}

export function parameterNames(catalog: Catalog): string[] {
  return catalog.flatMap((entry) => entry.parameters.map((p) => `${entry.id}.${p.name}`));
}

export function erratumChecks(entry: Erratum): string {
  return `${entry.id}: ${entry.checks.join(", ")}`;
}
