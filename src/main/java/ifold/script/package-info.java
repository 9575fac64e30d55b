/**
 * Fold scripts: a paper and a list of folds, built in code ({@link ifold.script.FoldScript#builder()})
 * or read from a small text format (docs/fold-scripts.md), and played into the states of the
 * paper one fold after another. Pure Java: no GL.
 */
package ifold.script;
