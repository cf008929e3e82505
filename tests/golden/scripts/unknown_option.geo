// A misspelled option is not fatal: it warns, names the nearest option, and the run goes on.
Mesh.MeshSizeMaximum = 0.5;
Printf("still running");
