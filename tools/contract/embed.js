  /** @typedef {import("./openapi").components["schemas"]["CurveResponse"]} Curve (float64) */
  const api = "http://127.0.0.1:8000";
  /** @type {Curve} */
  const curve = await (await fetch(`${api}/discretizations/d4b?h=1&d=0.1&i_min=-10&i_max=10`)).json();
  const xs = curve.vertices.map(([x]) => x), ys = curve.vertices.map(([, y]) => y);
  const svg = /** @type {HTMLElement} */ (document.getElementById("curve"));
  svg.setAttribute("viewBox", `${Math.min(...xs)} ${-Math.max(...ys)} ${Math.max(...xs) - Math.min(...xs)} ${Math.max(...ys) - Math.min(...ys)}`);
  const line = document.createElementNS("http://www.w3.org/2000/svg", "polyline");
  line.setAttribute("points", curve.vertices.map(([x, y]) => `${x},${-y}`).join(" "));
  line.setAttribute("fill", "none"); line.setAttribute("stroke", "steelblue"); line.setAttribute("stroke-width", "0.02");
  svg.append(line);
