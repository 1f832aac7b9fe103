// The page's words in English and Spanish (gcnc studio --lang en|es); gcnc's messages come from the server
// in the same language (tables/errors.csv).
const WORDS = {
  en: {
    program: "Program", new: "New", save: "Save", saveas: "Save as…", compile: "Compile",
    errors: "Errors", code: "Code", message: "Message", line: "Line", column: "Column",
    toolpath: "Tool path (X as diameter, Z along)", galil: "Galil DMC",
    noErrors: "no errors", nErrors: (e, w) => `${e} error${e === 1 ? "" : "s"}, ${w} warning${w === 1 ? "" : "s"}`,
    cursor: (l, c) => `Line ${l}, column ${c}`,
    unsaved: "unsaved changes", saved: (n) => `saved ${n}`, opened: (n) => `opened ${n}`,
    saveFailed: (m) => `not saved: ${m} — your text is still here`,
    askName: "Name of the new program (relative to the folder, e.g. part.nc):",
    askSaveAs: "Save as (relative to the folder):",
    overwrite: (n) => `${n} exists or changed on disk. Overwrite it?`,
    discard: "This program has unsaved changes. Discard them?",
    compiling: "compiling…", compiled: (d, m) => `compiled: wrote ${d} and ${m}`,
    compileFailed: (n) => `not compiled: ${n}; nothing written`,
    noPath: "No path: the program has errors (or nothing moved).",
    stalePath: "The program has errors: the path and the DMC shown are those of its last version without errors.",
    cycle: "Cycle time", extents: "Envelope (machine mm, X as radius)", blocks: "Blocks", dmcLines: "DMC lines",
    noProgram: "No programs in this folder yet: New makes one.",
    offline: "the studio is not answering (stopped?)", untitled: "(no program)",
  },
  es: {
    program: "Programa", new: "Nuevo", save: "Guardar", saveas: "Guardar como…", compile: "Compilar",
    errors: "Errores", code: "Código", message: "Mensaje", line: "Línea", column: "Columna",
    toolpath: "Trayectoria (X como diámetro, Z a lo largo)", galil: "DMC de Galil",
    noErrors: "sin errores", nErrors: (e, w) => `${e} error${e === 1 ? "" : "es"}, ${w} aviso${w === 1 ? "" : "s"}`,
    cursor: (l, c) => `Línea ${l}, columna ${c}`,
    unsaved: "cambios sin guardar", saved: (n) => `guardado ${n}`, opened: (n) => `abierto ${n}`,
    saveFailed: (m) => `no se guardó: ${m} — su texto sigue aquí`,
    askName: "Nombre del programa nuevo (relativo a la carpeta, p. ej. pieza.nc):",
    askSaveAs: "Guardar como (relativo a la carpeta):",
    overwrite: (n) => `${n} ya existe o cambió en el disco. ¿Sobrescribirlo?`,
    discard: "Este programa tiene cambios sin guardar. ¿Descartarlos?",
    compiling: "compilando…", compiled: (d, m) => `compilado: se escribieron ${d} y ${m}`,
    compileFailed: (n) => `no se compiló: ${n}; no se escribió nada`,
    noPath: "Sin trayectoria: el programa tiene errores (o nada se movió).",
    stalePath: "El programa tiene errores: la trayectoria y el DMC que se ven son los de su última versión sin errores.",
    cycle: "Tiempo de ciclo", extents: "Envolvente (mm de máquina, X como radio)", blocks: "Bloques", dmcLines: "Líneas DMC",
    noProgram: "Aún no hay programas en esta carpeta: Nuevo crea uno.",
    offline: "el estudio no responde (¿detenido?)", untitled: "(ningún programa)",
  },
};

export const lang = document.body.dataset.lang === "es" ? "es" : "en";
export const t = WORDS[lang];

/** Fills every element marked data-t="key" with its word. */
export function translatePage() {
  for (const el of document.querySelectorAll("[data-t]")) {
    el.textContent = t[el.dataset.t];
  }
}
