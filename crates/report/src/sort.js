"use strict";
// Sorts a table.sortable by the clicked header: numbers by value, text alphabetically, blanks last.
function sortKey(row, column) {
  const cell = row.cells[column];
  const text = cell ? (cell.getAttribute("data-sort") ?? cell.textContent).trim() : "";
  if (text === "") return null;
  const number = Number(text);
  return Number.isNaN(number) ? text : number;
}
function sortBy(table, header, column) {
  const ascending = header.getAttribute("aria-sort") !== "ascending";
  for (const other of header.parentNode.cells) other.removeAttribute("aria-sort");
  header.setAttribute("aria-sort", ascending ? "ascending" : "descending");
  const body = table.tBodies[0];
  const rows = Array.from(body.rows);
  rows.sort((a, b) => {
    const x = sortKey(a, column);
    const y = sortKey(b, column);
    if (x === null || y === null) return x === y ? 0 : x === null ? 1 : -1;
    const order = typeof x === "number" && typeof y === "number" ? x - y : String(x).localeCompare(String(y));
    return ascending ? order : -order;
  });
  for (const row of rows) body.appendChild(row);
}
for (const table of document.querySelectorAll("table.sortable")) {
  const headers = table.tHead.rows[0].cells;
  for (let column = 0; column < headers.length; column++) {
    const header = headers[column];
    header.tabIndex = 0;
    header.addEventListener("click", () => sortBy(table, header, column));
    header.addEventListener("keydown", (event) => {
      if (event.key === "Enter") sortBy(table, header, column);
    });
  }
}
