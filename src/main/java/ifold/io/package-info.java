/** Files written whole or not at all, and the threads that data-parallel steps share. Plain Java. */
package ifold.io;
