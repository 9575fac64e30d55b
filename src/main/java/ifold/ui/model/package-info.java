/**
 * The desktop window's model, in plain Java so that it is tested without a display: the job
 * the window folds and its parameters as typed ({@link ifold.ui.model.Job}), checked by the
 * core so that a bad value is marked at its field with the command line's message
 * ({@link ifold.ui.model.Planning}); the folded result ready to show and export
 * ({@link ifold.ui.model.Plan}); planning and exporting off the event thread, cancellable,
 * with progress ({@link ifold.ui.model.Worker}); the timeline ({@link ifold.ui.model.Timeline});
 * and the settings kept between runs ({@link ifold.ui.model.Settings}). No Swing, no AWT.
 */
package ifold.ui.model;
