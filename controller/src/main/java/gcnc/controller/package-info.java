/**
 * The virtual Galil ({@code gcnc controller --virtual}, docs/virtual-controller.md): an independent
 * implementation of the controller's protocol, program threads and motion in time, a test fixture and a demo.
 */
package gcnc.controller;
