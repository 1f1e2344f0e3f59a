// three.js ships no type declarations (they are @types/three, not installed): its modules type as any.
declare module 'three';
declare module 'three/addons/*';
