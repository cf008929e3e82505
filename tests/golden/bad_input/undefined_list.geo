n = #missing[];
